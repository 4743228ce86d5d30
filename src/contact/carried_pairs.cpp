#include "contact/carried_pairs.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <iterator>

#include "contact/broad_phase.hpp"

namespace dda {
namespace {

Box grow(const Box& box, double margin) {
  Box g = box;
  g.min.array() -= margin;
  g.max.array() += margin;
  return g;
}

bool inside(const Box& inner, const Box& outer) {
  return outer.min.x() <= inner.min.x() && outer.min.y() <= inner.min.y() &&
         inner.max.x() <= outer.max.x() && inner.max.y() <= outer.max.y();
}

// Sweeping one block again tests it against every box (n tests); a new sweep sorts the n
// boxes (about n log2 n comparisons) and sorts its pairs. So up to about log2 n blocks that
// left their box are swept again one by one, more by a new sweep.
std::size_t partial_limit(std::size_t n) { return static_cast<std::size_t>(std::bit_width(n)); }

void sweep_all(const std::vector<Box>& boxes, double margin, CarriedPairs& carried) {
  carried.grown.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) carried.grown[i] = grow(boxes[i], margin);
  carried.pairs = overlapping_pairs(carried.grown);
  ++carried.full_sweeps;
}

// New grown boxes for the blocks in `left`, and their pairs found again against every box;
// the pairs of the others stay (their grown boxes have not changed).
void sweep_again(const std::vector<Box>& boxes, double margin, const std::vector<int>& left,
                 CarriedPairs& carried) {
  const int n = static_cast<int>(boxes.size());
  std::vector<unsigned char> moved(boxes.size(), 0);
  for (const int i : left) {
    carried.grown[static_cast<std::size_t>(i)] = grow(boxes[static_cast<std::size_t>(i)], margin);
    moved[static_cast<std::size_t>(i)] = 1;
  }
  const auto involves_moved = [&](const std::pair<int, int>& p) {
    return moved[static_cast<std::size_t>(p.first)] != 0 ||
           moved[static_cast<std::size_t>(p.second)] != 0;
  };
  std::erase_if(carried.pairs, involves_moved);
  std::vector<std::pair<int, int>> added;
  for (const int i : left) {
    const Box& a = carried.grown[static_cast<std::size_t>(i)];
    for (int j = 0; j < n; ++j) {
      // A pair of two blocks that both left is added once, from the lower index.
      if (j == i || (moved[static_cast<std::size_t>(j)] != 0 && j < i)) continue;
      if (boxes_overlap(a, carried.grown[static_cast<std::size_t>(j)])) {
        added.emplace_back(std::min(i, j), std::max(i, j));
      }
    }
  }
  std::sort(added.begin(), added.end());
  std::vector<std::pair<int, int>> merged;
  merged.reserve(carried.pairs.size() + added.size());
  std::merge(carried.pairs.begin(), carried.pairs.end(), added.begin(), added.end(),
             std::back_inserter(merged));
  carried.pairs = std::move(merged);
  ++carried.partial_sweeps;
}

}  // namespace

void carried_overlapping_pairs(const std::vector<Box>& boxes, double margin, CarriedPairs& carried,
                               std::vector<std::pair<int, int>>& out) {
  margin = margin > 0.0 ? margin : 0.0;  // (a box must lie inside its grown box)
  if (carried.grown.size() != boxes.size()) {
    sweep_all(boxes, margin, carried);
  } else {
    std::vector<int> left;  // blocks whose present box is not inside their grown one
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      if (!inside(boxes[i], carried.grown[i])) left.push_back(static_cast<int>(i));
    }
    if (left.empty()) {
      ++carried.kept;
    } else if (left.size() > partial_limit(boxes.size())) {
      sweep_all(boxes, margin, carried);
    } else {
      sweep_again(boxes, margin, left, carried);
    }
  }
  // Every present box lies inside its grown box (exact comparisons above, or just grown from
  // it), so two present boxes that overlap have grown boxes that overlap: their pair is in
  // the list, and the filter keeps exactly the pairs a sweep of the present boxes finds, in
  // the same increasing order.
  out.clear();
  for (const std::pair<int, int>& p : carried.pairs) {
    const Box& a = boxes[static_cast<std::size_t>(p.first)];
    const Box& b = boxes[static_cast<std::size_t>(p.second)];
    if (boxes_overlap(a, b)) out.push_back(p);
  }
}

}  // namespace dda
