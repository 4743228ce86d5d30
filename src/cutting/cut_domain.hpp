// Block cutting (issue 11): a domain polygon cut by joint segments into blocks. The geometry
// is CGAL's 2D arrangement with exact predicates and constructions, kept inside
// cut_domain.cpp (the one file that includes CGAL, which is slow to compile) behind this
// plain-double interface.
#pragma once

#include <vector>

#include "kinematics/types.hpp"

namespace dda {

struct JointSegment {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
};

struct CutResult {
  // The blocks: simple polygons, counter-clockwise, collinear vertices merged, convex or not.
  std::vector<Polygon> blocks;
  // Edges left by traces that end inside a block (the same block on both sides), removed.
  int dead_end_edges = 0;
  // Blocks that enclosed another (a closed loop of traces touching nothing else): each such
  // block is split by a segment from its hole to its outer boundary, so that every block is
  // a simple polygon (the segment is a joint of the cut, of the default joint material).
  int holes_bridged = 0;
  // Blocks smaller than min_block_area merged into a neighbour (slivers).
  int slivers_merged = 0;
};

// Cuts the counter-clockwise simple polygon `domain` by the segments `joints` (which may
// cross the domain's boundary or lie partly outside; only what lies inside cuts). Every
// segment is inserted in one sweep (CGAL::insert of the whole range). A block of less than
// `min_block_area` (m^2) is merged into the neighbour with which it shares its longest
// edge (the edge removed, and any dead end that leaves), until none is left that has a
// neighbour inside the domain.
CutResult cut_domain(const Polygon& domain, const std::vector<JointSegment>& joints,
                     double min_block_area = 0.0);

}  // namespace dda
