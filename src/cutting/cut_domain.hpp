// Block cutting: a domain polygon cut by joint segments into blocks. The geometry
// is CGAL's 2D arrangement with exact predicates and constructions, kept inside
// cut_domain.cpp (the one file that includes CGAL, which is slow to compile) behind this
// plain-double interface.
#pragma once

#include <utility>
#include <vector>

#include "kinematics/types.hpp"

namespace dda {

// A joint segment and the group it belongs to (a joint set, a single joint: whatever the
// caller numbers, >= 0), so that the cut can say which group made each edge between two
// blocks. -1 is no group: the default joint.
struct JointSegment {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  int group = -1;
};

// Two blocks that share edges (indices into CutResult::blocks, a < b), the total length
// they share, and the group of the segments that made the shared edges. Edges of several
// groups between one pair: the group with the longest shared length (the lower group on a
// tie). An edge made by several overlapping segments has the highest of their groups.
// Hole bridges have group -1, and so do pieces of the domain's boundary (never shared).
struct BlockAdjacency {
  int a = 0;
  int b = 0;
  int group = -1;
  double shared_length = 0.0;
};

struct CutResult {
  // The blocks: simple polygons, counter-clockwise, collinear vertices merged, convex or not.
  std::vector<Polygon> blocks;
  // Edges left by traces that end inside a block (the same block on both sides), removed.
  int dead_end_edges = 0;
  // Blocks that enclosed another (a closed loop of traces touching nothing else): each such
  // block is split by two segments from its hole to what surrounds it, so that every block
  // is a simple polygon (the segments are joints of the cut, of the default joint material).
  int holes_bridged = 0;
  // Blocks smaller than min_block_area merged into a neighbour (slivers).
  int slivers_merged = 0;
  // Faces left out because they have no area once their corners are rounded to doubles
  // (narrower than 1e-11 of their size): slivers when min_block_area does not merge them.
  int collapsed_faces = 0;
  // Every pair of blocks sharing an edge of positive length, sorted by (a, b).
  std::vector<BlockAdjacency> adjacency;
  // Per block, per edge (edge k from vertex k to vertex k + 1): the length of each joint
  // group's part of it (group, m; by group; -1 for the domain's boundary and hole bridges).
  // One part where the edge lies on one joint, however many arrangement edges make it; a
  // line of a set cut with its rock bridges gives the traces' and the bridges' parts.
  std::vector<std::vector<std::vector<std::pair<int, double>>>> edge_parts;
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
