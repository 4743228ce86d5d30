#include "contact/broad_phase.hpp"

#include <algorithm>
#include <numeric>

namespace dda {
namespace {

// The axis to sweep along (0: x, 1: y): the one along which the boxes' mean length is the
// smaller share of their span, so that fewer boxes start before another ends. A tall column
// of blocks is swept along y: along x every block overlaps every other, n^2 / 2 pairs looked
// at every step for the n - 1 that touch.
int sweep_axis(const std::vector<Box>& boxes) {
  if (boxes.empty()) return 0;
  Vec2 lo = boxes[0].min, hi = boxes[0].max, length = Vec2::Zero();
  for (const Box& b : boxes) {
    lo = lo.cwiseMin(b.min);
    hi = hi.cwiseMax(b.max);
    length += b.max - b.min;
  }
  const Vec2 span = hi - lo;
  // length / span compared without dividing (a span may be 0: all boxes at one place).
  return length.x() * span.y() <= length.y() * span.x() ? 0 : 1;
}

}  // namespace

Box grown_box(const Polygon& poly, double margin) {
  Box box = bounding_box(poly);
  box.min.array() -= margin;
  box.max.array() += margin;
  return box;
}

std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Box>& boxes) {
  const int n = static_cast<int>(boxes.size());
  const int axis = sweep_axis(boxes), other = 1 - axis;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return boxes[a].min[axis] < boxes[b].min[axis]; });
  std::vector<std::pair<int, int>> pairs;
  for (int k = 0; k < n; ++k) {
    const Box& a = boxes[order[k]];
    // Sweep on while the next box starts before this one ends along the axis.
    for (int m = k + 1; m < n && boxes[order[m]].min[axis] <= a.max[axis]; ++m) {
      const Box& b = boxes[order[m]];
      if (b.min[other] <= a.max[other] && a.min[other] <= b.max[other]) {
        pairs.emplace_back(std::min(order[k], order[m]), std::max(order[k], order[m]));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::optional<std::pair<int, int>> first_overlapping_pair(
    const std::vector<Box>& boxes, const std::function<bool(int, int)>& overlap) {
  const int n = static_cast<int>(boxes.size());
  if (n < 2) return std::nullopt;
  const int axis = sweep_axis(boxes), other = 1 - axis;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return boxes[a].min[axis] < boxes[b].min[axis] ||
           (boxes[a].min[axis] == boxes[b].min[axis] && a < b);
  });
  for (int k = 0; k < n; ++k) {
    const Box& a = boxes[order[k]];
    for (int m = k + 1; m < n && boxes[order[m]].min[axis] <= a.max[axis]; ++m) {
      const Box& b = boxes[order[m]];
      if (b.min[other] <= a.max[other] && a.min[other] <= b.max[other]) {
        const int i = std::min(order[k], order[m]), j = std::max(order[k], order[m]);
        if (overlap(i, j)) return std::pair(i, j);
      }
    }
  }
  return std::nullopt;
}

}  // namespace dda
