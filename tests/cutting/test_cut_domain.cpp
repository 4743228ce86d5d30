// Block cutting's geometry (cutting/cut_domain): a domain cut by joint segments
// with CGAL's exact arrangement. Checked against what a cut must keep: the blocks' areas sum
// to the domain's, no two blocks overlap, every block is a simple counter-clockwise polygon,
// dead-end traces leave nothing inside a block, and a hole is bridged.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "cutting/cut_domain.hpp"
#include "kinematics/overlap.hpp"
#include "kinematics/polygon.hpp"

using namespace dda;

namespace {

double total_area(const std::vector<Polygon>& blocks) {
  double a = 0.0;
  for (const Polygon& p : blocks) a += signed_area(p);
  return a;
}

// Every block simple and counter-clockwise, and no two overlapping (touching is allowed:
// the overlap test's tolerance is 1e-9 of the domain's size).
void check_blocks_valid(const std::vector<Polygon>& blocks, double size) {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    INFO("block " << i);
    CHECK(signed_area(blocks[i]) > 0.0);
    CHECK_FALSE(is_self_intersecting(blocks[i]));
    for (std::size_t j = i + 1; j < blocks.size(); ++j) {
      INFO("and block " << j);
      CHECK_FALSE(polygons_overlap(blocks[i], blocks[j], 1e-9 * size));
    }
  }
}

}  // namespace

TEST_CASE("a square cut by a grid of full traces gives the grid's blocks", "[cutting]") {
  // 10 m x 10 m, horizontal traces every 1 m and vertical ones every 2 m, each running past
  // the boundary: 10 rows x 5 columns of 2 m x 1 m blocks, each with 4 vertices (the
  // crossings on its sides are the neighbours' corners, collinear on its own sides, and
  // merged). Areas are sums of products of exact coordinates: 1e-12 relative.
  const Polygon domain{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  std::vector<JointSegment> joints;
  for (int k = 1; k < 10; ++k) joints.push_back({{-1.0, k}, {11.0, k}});
  for (int k = 1; k < 5; ++k) joints.push_back({{2.0 * k, -1.0}, {2.0 * k, 11.0}});
  const CutResult cut = cut_domain(domain, joints);
  REQUIRE(cut.blocks.size() == 50);
  CHECK(cut.dead_end_edges == 0);
  for (const Polygon& b : cut.blocks) {
    CHECK(b.size() == 4);
    CHECK(signed_area(b) == Approx(2.0).epsilon(1e-12));
  }
  CHECK(total_area(cut.blocks) == Approx(100.0).epsilon(1e-12));
  check_blocks_valid(cut.blocks, 10.0);
}

TEST_CASE("a trace ending inside a block leaves no edge in it", "[cutting]") {
  // One full horizontal trace at y = 5, and a vertical one from (5, 1) to (5, 8) that
  // crosses it: below y = 5 the piece (5,1)-(5,5) and above it (5,5)-(5,8) both have the
  // same block on both sides: two dead-end edges removed, two rectangles left.
  const Polygon domain{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const CutResult cut = cut_domain(domain, {{{-1, 5}, {11, 5}}, {{5, 1}, {5, 8}}});
  REQUIRE(cut.blocks.size() == 2);
  CHECK(cut.dead_end_edges == 2);
  for (const Polygon& b : cut.blocks) {
    CHECK(b.size() == 4);  // no vertex left at (5, 5) or at the trace's ends
    CHECK(signed_area(b) == Approx(50.0).epsilon(1e-12));
  }
}

TEST_CASE("a concave domain cut by random traces keeps its area and no overlaps",
          "[cutting]") {
  // An L-shaped domain (area 300 m^2) and 60 random traces of 4 to 20 m, many ending
  // inside blocks or outside the domain: the blocks tile the domain exactly (1e-9 relative:
  // the corners are exact intersections rounded to doubles once, ~1e-16 m each, over
  // hundreds of blocks), none overlaps another, each is simple and counter-clockwise.
  const Polygon domain{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(-2.0, 22.0), angle(0.0, M_PI), length(4.0, 20.0);
  std::vector<JointSegment> joints;
  for (int k = 0; k < 60; ++k) {
    const Vec2 c(pos(rng), pos(rng));
    const double a = angle(rng), l = length(rng);
    const Vec2 half = 0.5 * l * Vec2(std::cos(a), std::sin(a));
    joints.push_back({c - half, c + half});
  }
  const CutResult cut = cut_domain(domain, joints);
  INFO(cut.blocks.size() << " blocks, " << cut.dead_end_edges << " dead-end edges");
  CHECK(cut.blocks.size() > 20);
  CHECK(cut.dead_end_edges > 0);
  CHECK(total_area(cut.blocks) == Approx(300.0).epsilon(1e-9));
  check_blocks_valid(cut.blocks, 20.0);
  // Concave blocks are kept: the domain's reflex corner (10, 10) lies on some block.
  bool corner = false;
  for (const Polygon& b : cut.blocks) {
    for (const Vec2& v : b) corner |= (v - Vec2(10, 10)).norm() < 1e-12;
  }
  CHECK(corner);
}

TEST_CASE("joints leaving and re-entering a notched domain cut it as if whole",
          "[cutting]") {
  // A U (30 m x 20 m with a 10 m x 10 m notch from the top, area 500 m^2). Each joint is
  // inserted only from just before its first crossing of the boundary to just after its
  // last (the cut of a long thin domain used to spend minutes removing the mesh of
  // crossings outside it), so these check what must survive that: y = 15 leaves the left
  // prong and re-enters the right one (the part across the notch stays, and is removed
  // outside); a joint wholly in the notch is dropped; one along the base edge is kept. The
  // grid x = 5, 15, 25 and y = 5, 15 makes 12 blocks: 3 in each outer column; in each inner
  // column a 10 x 5 rectangle below, an L of 75 m^2 around the notch's corner, and a
  // 5 x 5 square at the prong's top.
  const Polygon domain{{0, 0}, {30, 0}, {30, 20}, {20, 20}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
  const std::vector<JointSegment> joints{
      {{-5, 5}, {35, 5}},    {{-5, 15}, {35, 15}},  {{5, -5}, {5, 25}}, {{15, -5}, {15, 25}},
      {{25, -5}, {25, 25}},  {{12, 15}, {18, 16}},  {{-5, 0}, {35, 0}}};
  const CutResult cut = cut_domain(domain, joints);
  CHECK(cut.blocks.size() == 12);
  CHECK(total_area(cut.blocks) == Approx(500.0).epsilon(1e-12));
  check_blocks_valid(cut.blocks, 30.0);
  int squares = 0, rectangles = 0, ells = 0;
  for (const Polygon& b : cut.blocks) {  // exact: every corner is on the integer grid
    const double a = signed_area(b);
    squares += a == Approx(25.0).epsilon(1e-12) && b.size() == 4;
    rectangles += a == Approx(50.0).epsilon(1e-12) && b.size() == 4;
    ells += a == Approx(75.0).epsilon(1e-12) && b.size() == 6;
  }
  CHECK(squares == 6);
  CHECK(rectangles == 4);
  CHECK(ells == 2);
}

TEST_CASE("a joint given many times cuts once, with the highest of its groups", "[cutting]") {
  // Two sets of one dip, spacing and offset draw the same segments; CGAL's sweep met k copies
  // of a curve pair by pair (a model whose two sets were listed 1500 times each cut for
  // minutes). Copies go in once, reversed ones too, with the highest group, as overlapping
  // segments give their edge. A 10 x 10 square cut by x = 5 (groups 0, 3 and 1, one copy
  // reversed) and y = 5 (group 2, twice): four 5 x 5 blocks; the pairs across x = 5 carry
  // group 3, those across y = 5 group 2.
  const Polygon domain{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  std::vector<JointSegment> joints{{{5, -1}, {5, 11}, 0}, {{5, 11}, {5, -1}, 3},
                                   {{-1, 5}, {11, 5}, 2}, {{5, -1}, {5, 11}, 1},
                                   {{-1, 5}, {11, 5}, 2}};
  for (int k = 0; k < 1000; ++k) joints.push_back({{5, -1}, {5, 11}, 0});
  const CutResult cut = cut_domain(domain, joints);
  REQUIRE(cut.blocks.size() == 4);
  CHECK(total_area(cut.blocks) == Approx(100.0).epsilon(1e-12));
  REQUIRE(cut.adjacency.size() == 4);
  for (const BlockAdjacency& a : cut.adjacency) {
    const Vec2 ca = polygon_moments(cut.blocks[a.a]).centroid;
    const Vec2 cb = polygon_moments(cut.blocks[a.b]).centroid;
    const bool across_x = std::abs(ca.x() - cb.x()) > 1.0;  // side by side: across x = 5
    CHECK(a.group == (across_x ? 3 : 2));
    CHECK(a.shared_length == Approx(5.0).epsilon(1e-12));
  }
}

TEST_CASE("a block enclosing another is bridged into simple polygons", "[cutting]") {
  // A closed square of traces (3,3)-(7,7) inside a 10 m square touches nothing: the outer
  // block would have a hole. Two bridges, from the hole's lowest-left corner (3, 3) down to
  // (3, 0) and from its highest-right corner (7, 7) up to (7, 10), split it into two simple
  // blocks of 42 m^2 (3 x 10 + 4 x 3 each); the hole is a block of 16 m^2. One bridge alone
  // would leave a slit (the same block on both sides of it), which the scene reader rejects
  // as a polygon that touches itself.
  const Polygon domain{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const CutResult cut = cut_domain(
      domain, {{{3, 3}, {7, 3}}, {{7, 3}, {7, 7}}, {{7, 7}, {3, 7}}, {{3, 7}, {3, 3}}});
  CHECK(cut.holes_bridged == 1);
  REQUIRE(cut.blocks.size() == 3);
  std::vector<double> areas;
  for (const Polygon& b : cut.blocks) areas.push_back(signed_area(b));
  std::sort(areas.begin(), areas.end());
  CHECK(areas[0] == Approx(16.0).epsilon(1e-12));
  CHECK(areas[1] == Approx(42.0).epsilon(1e-12));
  CHECK(areas[2] == Approx(42.0).epsilon(1e-12));
  CHECK(total_area(cut.blocks) == Approx(100.0).epsilon(1e-12));
  check_blocks_valid(cut.blocks, 10.0);
  // The two halves touch each other only across the bridges (3 + 3 m), each touches the
  // hole's block; the bridges are of no group.
  REQUIRE(cut.adjacency.size() == 3);
  for (const BlockAdjacency& pair : cut.adjacency) {
    const bool halves =
        signed_area(cut.blocks[pair.a]) > 20 && signed_area(cut.blocks[pair.b]) > 20;
    if (halves) {
      CHECK(pair.group == -1);
      CHECK(pair.shared_length == Approx(6.0).epsilon(1e-12));
    }
  }
}

TEST_CASE("each pair of neighbours has the group of the segments along their shared edge",
          "[cutting]") {
  // Horizontal traces at y = 2.5, 5, 7.5 of group 0 and a vertical one at x = 5 of group 3:
  // 4 rows x 2 columns; pairs one above the other share 5 m of group 0, pairs side by side
  // 2.5 m of group 3. Lengths between exact corners on axis-parallel lines: 1e-12.
  const Polygon domain{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  std::vector<JointSegment> joints;
  for (int k = 1; k < 4; ++k) joints.push_back({{-1.0, 2.5 * k}, {11.0, 2.5 * k}, 0});
  joints.push_back({{5.0, -1.0}, {5.0, 11.0}, 3});
  const CutResult cut = cut_domain(domain, joints);
  REQUIRE(cut.blocks.size() == 8);
  REQUIRE(cut.adjacency.size() == 6 + 4);
  for (const BlockAdjacency& pair : cut.adjacency) {
    CHECK(pair.a < pair.b);
    const Vec2 ca = polygon_moments(cut.blocks[pair.a]).centroid;
    const Vec2 cb = polygon_moments(cut.blocks[pair.b]).centroid;
    const bool side_by_side = std::abs(ca.y() - cb.y()) < 1e-9;
    CHECK(pair.group == (side_by_side ? 3 : 0));
    CHECK(pair.shared_length == Approx(side_by_side ? 2.5 : 5.0).epsilon(1e-12));
  }
  // A segment of group 5 along the trace y = 5 (overlapping it): the edge takes the higher
  // group, so the two pairs across y = 5 are of group 5.
  joints.push_back({{-2.0, 5.0}, {12.0, 5.0}, 5});
  const CutResult overlaid = cut_domain(domain, joints);
  int fives = 0;
  for (const BlockAdjacency& pair : overlaid.adjacency) fives += pair.group == 5 ? 1 : 0;
  CHECK(fives == 2);
}

TEST_CASE("each edge of a block has the group of the joint it lies on, the boundary none",
          "[cutting]") {
  // A 10 m square, a horizontal joint y = 4 (group 0) and a vertical one x = 6 from the
  // joint up (group 1): three blocks. The lower block's top edge is one edge of the polygon
  // but two halfedges (x = 6 ends on it), both of group 0; the upper-left block meets the
  // lower one along y = 4 and the upper-right one along x = 6, one pair with two groups:
  // the pair has group 0 (its longest shared length, 6 m against 6 m, the lower group on a
  // tie), each edge its own.
  const Polygon domain{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const CutResult cut = cut_domain(domain, {{{-1, 4}, {11, 4}, 0}, {{6, 4}, {6, 11}, 1}});
  REQUIRE(cut.blocks.size() == 3);
  REQUIRE(cut.edge_parts.size() == 3);
  for (std::size_t i = 0; i < cut.blocks.size(); ++i) {
    const Polygon& b = cut.blocks[i];
    REQUIRE(cut.edge_parts[i].size() == b.size());
    for (std::size_t k = 0; k < b.size(); ++k) {
      const Vec2 p = b[k], q = b[(k + 1) % b.size()];
      const Vec2 m = 0.5 * (p + q);
      INFO("block " << i << " edge " << k << " middle " << m.transpose());
      const bool on_boundary = m.x() == 0.0 || m.x() == 10.0 || m.y() == 0.0 || m.y() == 10.0;
      const int expected = on_boundary ? -1 : (m.y() == 4.0 ? 0 : 1);
      // One part, the whole edge: axis-parallel lengths between exact corners, summed (6 + 4
      // on the lower block's top): exact in doubles.
      REQUIRE(cut.edge_parts[i][k].size() == 1);
      CHECK(cut.edge_parts[i][k][0].first == expected);
      CHECK(cut.edge_parts[i][k][0].second == (q - p).norm());
    }
  }
}

TEST_CASE("a trace through a corner of the domain leaves no edge too short to keep",
          "[cutting]") {
  // A trace at 25 degrees through the origin, a corner of the domain: rounding puts its
  // crossing with the side x = 0 a few 1e-16 m above the corner (an edge the scene reader
  // would take for a repeated vertex). The two points become the corner itself.
  const Polygon domain{{0, 0}, {20, 0}, {20, 10}, {0, 10}};
  const double a = 25.0 * M_PI / 180.0;
  const Vec2 d(std::cos(a), std::sin(a));
  const Vec2 n(-d.y(), d.x()), centre(10, 5);
  const Vec2 p = centre - n.dot(centre) * n;  // the line's point nearest the centre
  const CutResult cut = cut_domain(domain, {{p - 30.0 * d, p + 30.0 * d}});
  REQUIRE(cut.blocks.size() == 2);
  for (const Polygon& b : cut.blocks) {
    for (std::size_t i = 0; i < b.size(); ++i) {
      // Edges at least 1e-12 of the domain's diagonal (22.4 m) long: the reader's bound.
      CHECK((b[i] - b[(i + 1) % b.size()]).norm() > 1e-12 * 22.4);
    }
  }
  CHECK(total_area(cut.blocks) == Approx(200.0).epsilon(1e-12));
}

TEST_CASE("a sliver below the smallest block area is merged into a neighbour", "[cutting]") {
  // Traces at y = 5 and y = 5.01 leave a 10 m x 1 cm strip (0.1 m^2) between blocks of 50
  // and 49.9 m^2. With a smallest area of 0.5 m^2 it joins one of them (it shares a 10 m
  // edge with each, a tie): two blocks, 50.1 and 49.9 m^2 or 50 and 50, nothing lost; with
  // none, three.
  const Polygon domain{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const std::vector<JointSegment> joints{{{-1, 5}, {11, 5}}, {{-1, 5.01}, {11, 5.01}}};
  const CutResult all = cut_domain(domain, joints);
  CHECK(all.blocks.size() == 3);
  CHECK(all.slivers_merged == 0);
  const CutResult merged = cut_domain(domain, joints, 0.5);
  CHECK(merged.slivers_merged == 1);
  REQUIRE(merged.blocks.size() == 2);
  const double a0 = signed_area(merged.blocks[0]), a1 = signed_area(merged.blocks[1]);
  const double low = std::min(a0, a1);
  CHECK((low == Approx(49.9).epsilon(1e-12) || low == Approx(50.0).epsilon(1e-12)));
  for (const Polygon& b : merged.blocks) CHECK(b.size() == 4);  // no vertex left mid-side
  CHECK(total_area(merged.blocks) == Approx(100.0).epsilon(1e-12));
}

TEST_CASE("a joint along a domain edge, rounded a hair off it, cuts no sliver: its stretch "
          "along the edge is left out and its pieces end at the edge's corners",
          "[cutting]") {
  // The small slope's profile: a 45-degree face from (3, 3) to (10, 10). A joint through the
  // face's line drawn as a trace of dip 45 is, in doubles, a hair off y = x (cos and sin of
  // pi/4 differ in the last bit): it runs inside the domain below the toe platform, from
  // (0, 0) to the toe (3, 3), then along the face. Before, the stretch along the face cut a
  // sliver of no thickness that merged into its neighbour as a polygon crossing itself.
  const Polygon domain{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {3, 3}, {0, 3}};
  const double c = std::cos(M_PI / 4.0), s = std::sin(M_PI / 4.0);
  REQUIRE(c != s);  // the hair
  const std::vector<JointSegment> joints{{{-2.0 * c, -2.0 * s}, {20.0 * c, 20.0 * s}}};
  for (const double min_area : {0.0, 0.05}) {
    INFO("min_block_area " << min_area);
    const CutResult cut = cut_domain(domain, joints, min_area);
    // Two blocks: the triangle (0, 0), (3, 3), (0, 3) under the platform and the rest.
    REQUIRE(cut.blocks.size() == 2);
    CHECK(total_area(cut.blocks) == Approx(std::abs(signed_area(domain))).epsilon(1e-12));
    check_blocks_valid(cut.blocks, 20.0);
    const auto smaller = std::min_element(cut.blocks.begin(), cut.blocks.end(),
                                          [](const Polygon& a, const Polygon& b) {
                                            return signed_area(a) < signed_area(b);
                                          });
    // 4.5 m^2 to the joint's hair: the cut ends exactly at the face's corner (3, 3).
    CHECK(signed_area(*smaller) == Approx(4.5).epsilon(1e-12));
    CHECK(std::find(smaller->begin(), smaller->end(), Vec2(3.0, 3.0)) != smaller->end());
  }
}
