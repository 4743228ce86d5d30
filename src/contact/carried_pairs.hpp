// The broad phase carried from step to step (a Verlet list of boxes): the pairs whose boxes,
// grown by an extra margin, overlap. While every block's present box stays inside its grown
// box, the blocks whose present boxes overlap are among those pairs, and filtering the list
// by the present boxes gives exactly what a new sweep would; only the blocks that left their
// grown box are swept again. Pure functions over plain data.
#pragma once

#include <utility>
#include <vector>

#include "kinematics/polygon.hpp"

namespace dda {

// What is carried: each block's box grown by the margin when its pairs were last found, and
// all the pairs whose grown boxes overlap. Empty at first; a list made for another number of
// blocks is made again.
struct CarriedPairs {
  std::vector<Box> grown;                  // per block: its box then, grown by the margin
  std::vector<std::pair<int, int>> pairs;  // (i, j), i < j, whose grown boxes overlap, increasing
  // How the lists were kept up, counted over the calls (for tests and benchmarks): by a new
  // sweep of every block, by sweeping again only the blocks that left their grown box, or
  // as they were.
  long full_sweeps = 0;
  long partial_sweeps = 0;
  long kept = 0;
};

// The pairs (i, j), i < j, whose `boxes` overlap (boxes_overlap), in increasing order: the
// same list as overlapping_pairs(boxes), bit for bit, whatever `carried` holds (each call
// checks that the present boxes lie inside the carried ones, by exact comparison). The
// blocks whose present box is not inside its carried one get a new carried box, `boxes[i]`
// grown by `margin` (m, >= 0; less counts as 0) on every side, and new pairs. Writes into
// `out`, reusing its storage.
void carried_overlapping_pairs(const std::vector<Box>& boxes, double margin, CarriedPairs& carried,
                               std::vector<std::pair<int, int>>& out);

}  // namespace dda
