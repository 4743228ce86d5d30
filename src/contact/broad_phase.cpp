#include "contact/broad_phase.hpp"

#include <algorithm>
#include <numeric>

namespace dda {

Box grown_box(const Polygon& poly, double margin) {
  Box box = bounding_box(poly);
  box.min.array() -= margin;
  box.max.array() += margin;
  return box;
}

std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Box>& boxes) {
  const int n = static_cast<int>(boxes.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return boxes[a].min.x() < boxes[b].min.x(); });
  std::vector<std::pair<int, int>> pairs;
  for (int k = 0; k < n; ++k) {
    const Box& a = boxes[order[k]];
    // Sweep right while the next box starts before this one ends in x.
    for (int m = k + 1; m < n && boxes[order[m]].min.x() <= a.max.x(); ++m) {
      const Box& b = boxes[order[m]];
      if (b.min.y() <= a.max.y() && a.min.y() <= b.max.y()) {
        pairs.emplace_back(std::min(order[k], order[m]), std::max(order[k], order[m]));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace dda
