// Broad phase: which pairs of blocks are close enough to need a narrow-phase look.
// Sort and sweep along x over axis-aligned boxes, so the cost grows as N log N (plus the
// number of close pairs), not N^2. Pure function over plain data.
#pragma once

#include <utility>
#include <vector>

#include "kinematics/polygon.hpp"

namespace dda {

// Box of a polygon grown by `margin` on every side.
Box grown_box(const Polygon& poly, double margin);

// All pairs (i, j), i < j, whose boxes overlap (touching counts), in increasing (i, j)
// order.
std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Box>& boxes);

}  // namespace dda
