// Broad phase: which pairs of blocks are close enough to need a narrow-phase look.
// Sort and sweep over axis-aligned boxes, along the axis on which they lie side by side
// least (x for a wall, y for a column), so the cost grows as N log N (plus the pairs that
// overlap along that axis), not N^2. Pure function over plain data.
#pragma once

#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "kinematics/polygon.hpp"

namespace dda {

// Box of a polygon grown by `margin` on every side.
Box grown_box(const Polygon& poly, double margin);

// True when the two boxes overlap (touching counts): the rule overlapping_pairs applies.
inline bool boxes_overlap(const Box& a, const Box& b) {
  return a.min.x() <= b.max.x() && b.min.x() <= a.max.x() && a.min.y() <= b.max.y() &&
         b.min.y() <= a.max.y();
}

// All pairs (i, j), i < j, whose boxes overlap (boxes_overlap), in increasing (i, j) order
// (the same list whichever axis the sweep takes).
// (The sweep tests only the ends boxes_overlap needs: a box met later in the sweep starts no
// earlier in x, so it cannot end before the first one starts.)
std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Box>& boxes);

// The first pair (i, j), i < j, of boxes that overlap (boxes_overlap) for which
// `overlap(i, j)` is true, or nullopt when there is none. A sweep like overlapping_pairs',
// but along the axis on which the boxes lie side by side least (the smaller ratio of their
// mean length to their span), calling `overlap` on each pair as the sweep meets it and
// stopping at the first true: no list of pairs is kept (memory O(n)), and n identical or
// nested boxes stop at the first pair instead of building n^2 / 2 of them. "First" is the
// sweep's order (boxes by their lower end on the axis, then by index), not the list's.
// Cost O(n log n) plus the pairs side by side along the axis up to the one found.
std::optional<std::pair<int, int>> first_overlapping_pair(
    const std::vector<Box>& boxes, const std::function<bool(int, int)>& overlap);

}  // namespace dda
