// Joint water pressure from a phreatic line: the pressure resultant on a segment
// against hand integrals, the forces on a joint face, and the reader's checks.
#include <catch2/catch.hpp>

#include <cmath>

#include "io/scene_reader.hpp"
#include "solver/joint_water.hpp"

namespace {

using namespace dda;

}  // namespace

TEST_CASE("segment pressure: hydrostatic resultants and centres of pressure", "[water]") {
  WaterTable water;
  water.phreatic_line = {{-10.0, 5.0}, {10.0, 5.0}};  // flat at y = 5
  water.unit_weight = 1e4;
  // A vertical crack face from y = 5 down to y = -1 (depth 6): V = gamma z^2 / 2, acting at
  // two thirds of the depth (Hoek and Bray's tension-crack thrust).
  SegmentPressure p = segment_pressure(water, {0.0, 5.0}, {0.0, -1.0});
  // Exact integrals of a linear pressure; only round-off differs.
  CHECK(p.force == Approx(0.5 * 1e4 * 36.0).epsilon(1e-13));
  CHECK(p.centre.y() == Approx(5.0 - 4.0).epsilon(1e-13));
  // Half the segment above the water: only the wetted part counts.
  p = segment_pressure(water, {0.0, 11.0}, {0.0, -1.0});
  CHECK(p.force == Approx(0.5 * 1e4 * 36.0).epsilon(1e-13));
  CHECK(p.centre.y() == Approx(1.0).epsilon(1e-13));
  // Wholly above: nothing.
  CHECK(segment_pressure(water, {0.0, 6.0}, {3.0, 7.0}).force == 0.0);
  // A horizontal face 2 m under the table, 4 m long: uniform 2e4 Pa, 8e4 N at its middle.
  p = segment_pressure(water, {1.0, 3.0}, {5.0, 3.0});
  CHECK(p.force == Approx(8e4).epsilon(1e-13));
  CHECK(p.centre.x() == Approx(3.0).epsilon(1e-13));

  // A phreatic line with a kink at x = 0 (head 0 at x = -4, 4 at x = 0, 0 at x = 4, above a
  // horizontal face at y = 0): a triangle of pressure, 0.5 * 8 * 4 * gamma, centred at 0.
  WaterTable peak;
  peak.phreatic_line = {{-4.0, 0.0}, {0.0, 4.0}, {4.0, 0.0}};
  peak.unit_weight = 1.0;
  p = segment_pressure(peak, {-6.0, 0.0}, {6.0, 0.0});
  CHECK(p.force == Approx(16.0).epsilon(1e-13));
  CHECK(p.centre.x() == Approx(0.0).margin(1e-12));
  // Outside its ends the line is flat: heights there are its end heights.
  CHECK(phreatic_height(peak, -100.0) == 0.0);
  CHECK(phreatic_height(peak, 2.0) == Approx(2.0).epsilon(1e-15));
}

TEST_CASE("joint water forces push the two faces of a joint apart with the face's resultant",
          "[water]") {
  // Block 1, a 4 m x 1 m box, sits on block 0 at y = 0 (a face of 4 m); the table is 3 m
  // above the joint. Its two base vertices each carry half the face (Contact::length 2).
  const Polygon base{{-5, -2}, {5, -2}, {5, 0}, {-5, 0}};
  const Polygon box{{0, 0}, {4, 0}, {4, 1}, {0, 1}};
  std::vector<Contact> contacts(2);
  for (int k = 0; k < 2; ++k) {
    Contact& c = contacts[static_cast<std::size_t>(k)];
    c.key = {1, k, 0, 2};
    c.normal = {0.0, 1.0};
    c.tangent = {-1.0, 0.0};
    c.edge_start = {5.0, 0.0};  // the base's top edge, (5, 0) -> (-5, 0)
    c.edge_end = {-5.0, 0.0};
    c.length = 2.0;
  }
  WaterTable water;
  water.phreatic_line = {{-10.0, 3.0}, {10.0, 3.0}};
  const std::vector<BlockForce> forces = joint_water_forces(water, {&base, &box}, contacts, 0.01);
  Vec2 on_box = Vec2::Zero(), on_base = Vec2::Zero();
  double moment = 0.0;  // about the origin, on the box
  for (const BlockForce& f : forces) {
    (f.block == 1 ? on_box : on_base) += f.force;
    if (f.block == 1) moment += f.point.x() * f.force.y() - f.point.y() * f.force.x();
  }
  // U = gamma h L = 9810 x 3 x 4, upward on the box, at the face's middle (x = 2).
  CHECK(on_box.y() == Approx(9810.0 * 12.0).epsilon(1e-13));
  CHECK(on_box.x() == Approx(0.0).margin(1e-9));
  CHECK((on_box + on_base).norm() == Approx(0.0).margin(1e-9));
  CHECK(moment / on_box.y() == Approx(2.0).epsilon(1e-13));
}

TEST_CASE("an open joint seen from both sides is wetted once", "[water]") {
  // A vertical crack between block 0 (left) and block 1 (right), opened by 1 cm: block 1's
  // lower vertex sits on block 0's edge and block 0's lower vertex on block 1's edge, so
  // both lower halves of the face the two blocks share are shares of contacts. Counted per
  // contact, the lower half would be wet twice; per face, the thrust is gamma z^2 / 2 once.
  const Polygon left{{-4, 0}, {0, 0}, {0, 6}, {-4, 6}};
  const Polygon right{{0.01, -0.5}, {4, -0.5}, {4, 5.5}, {0.01, 5.5}};
  std::vector<Contact> contacts(3);
  contacts[0].key = {1, 3, 0, 1};  // right's top-left vertex on left's right edge
  contacts[1].key = {1, 0, 0, 1};  // right's bottom-left vertex on left's right edge
  contacts[2].key = {0, 1, 1, 3};  // left's bottom-right vertex on right's left edge
  for (int k = 0; k < 3; ++k) {
    Contact& c = contacts[static_cast<std::size_t>(k)];
    c.normal = k < 2 ? Vec2(1.0, 0.0) : Vec2(-1.0, 0.0);
    c.edge_start = k < 2 ? Vec2(0.0, 0.0) : Vec2(0.01, 5.5);  // left's edge 1, right's edge 3
    c.edge_end = k < 2 ? Vec2(0.0, 6.0) : Vec2(0.01, -0.5);
    c.length = 2.75;
  }
  WaterTable water;
  water.phreatic_line = {{-10.0, 6.0}, {10.0, 6.0}};
  water.unit_weight = 1.0;
  const std::vector<BlockForce> forces = joint_water_forces(water, {&left, &right}, contacts, 0.05);
  double on_right = 0.0;
  for (const BlockForce& f : forces) on_right += f.block == 1 ? f.force.x() : 0.0;
  // The faces overlap over y in [0, 5.5] (left's face ends at y = 0, right's at 5.5), and
  // each contact carries the half of that overlap next to its vertex: [2.75, 5.5] and
  // [0, 2.75] for right's vertices, [0, 2.75] for left's. Their union is [0, 5.5], and the
  // integral of (6 - y) over it is 33 - 5.5^2 / 2 = 17.875 (per contact it would be
  // 17.875 + 13.125 = 31). Exact integrals: round-off only. (Formerly each vertex
  // carried half its own face, so right's lower vertex wetted [-0.5, 2.5], a part of its
  // face that faces nothing of the left block: 21.)
  CHECK(on_right == Approx(17.875).epsilon(1e-12));
}

TEST_CASE("the water table is checked where it is read", "[water][input]") {
  const std::string blocks =
      R"("control": {"time_step": 0.01, "steps": 1},
         "materials": {"rock": {"model": "elastic", "density": 2500, "young": 1e9, "poisson": 0.25}},
         "blocks": [{"vertices": [[0,0],[1,0],[1,1],[0,1]], "material": "rock"}])";
  auto scene = [&](const std::string& water) {
    return "{" + blocks + ", \"water\": " + water + "}";
  };
  CHECK(parse_scene_text(scene(R"({"phreatic_line": [[0, 2], [5, 1]]})"), "s.json").water->unit_weight == 9810.0);
  CHECK_THROWS_WITH(parse_scene_text(scene(R"({"phreatic_line": [[0, 2], [0, 1]]})"), "s.json"),
                    Catch::Contains("s.json: water.phreatic_line[1]: x must increase"));
  CHECK_THROWS_WITH(parse_scene_text(scene(R"({"phreatic_line": [[0, 2]]})"), "s.json"),
                    Catch::Contains("water.phreatic_line"));
  CHECK_THROWS_WITH(parse_scene_text(scene(R"({"phreatic_line": [[0, 2], [1, 2]], "unit_weight": -1})"), "s.json"),
                    Catch::Contains("water.unit_weight"));
  CHECK_THROWS_WITH(parse_scene_text(scene(R"({"phreatic": [[0, 2], [1, 2]]})"), "s.json"),
                    Catch::Contains("water"));
}

TEST_CASE("a table filled a share of the way from its dry line presses as the line between",
          "[water]") {
  // Hoek & Bray's drained tension crack: the full line from the toe (0, 0) to the crack's top
  // (10, 14), the dry one to its bottom (10, 0). Filled 0.5, the table is the straight line to
  // (10, 7): the crack's face from (10, 0) up carries gamma zw^2 / 2 with zw = 7, and a base
  // segment along y = 0 the triangle gamma 7 x / 10 integrated, as the explicit line does.
  WaterTable table;
  table.phreatic_line = {{0.0, 0.0}, {10.0, 14.0}};
  table.dry_line = {{0.0, 0.0}, {10.0, 0.0}};
  table.fill = 0.5;
  table.unit_weight = 1e4;
  WaterTable line;
  line.phreatic_line = {{0.0, 0.0}, {10.0, 7.0}};
  line.unit_weight = 1e4;
  CHECK(phreatic_height(table, 4.0) == Approx(2.8).epsilon(1e-15));
  CHECK(phreatic_height(table, 20.0) == Approx(7.0).epsilon(1e-15));  // flat beyond the ends
  const SegmentPressure crack = segment_pressure(table, {10.0, 14.0}, {10.0, 0.0});
  CHECK(crack.force == Approx(0.5 * 1e4 * 49.0).epsilon(1e-13));
  const SegmentPressure base = segment_pressure(table, {0.0, 0.0}, {10.0, 0.0});
  CHECK(base.force == Approx(segment_pressure(line, {0.0, 0.0}, {10.0, 0.0}).force).epsilon(1e-13));
  CHECK(base.force == Approx(0.5 * 1e4 * 7.0 * 10.0).epsilon(1e-13));
  // Dry lines with vertices of their own: the head is linear only between both lines'
  // vertices, where the integral splits. A dry line kinked at x = 5 (down to y = -2) filled
  // 0 is the dry line itself: a base along y = -0.5 has the head 0.5 - 2x/5 up to x = 5 and
  // is wet only up to x = 1.25 (and from 8.75 on, alike); one along y = -3 carries the head
  // 3 - 2x/5, 1 at the kink, 3 again at x = 10.
  WaterTable kinked;
  kinked.phreatic_line = {{0.0, 0.0}, {10.0, 0.0}};
  kinked.dry_line = {{0.0, 0.0}, {5.0, -2.0}, {10.0, 0.0}};
  kinked.fill = 0.0;
  kinked.unit_weight = 1.0;
  CHECK(segment_pressure(kinked, {0.0, -0.5}, {10.0, -0.5}).force ==
        Approx(2.0 * (0.5 * 0.5 * 1.25)).epsilon(1e-13));  // two triangles, head 0.5 at the ends
  CHECK(segment_pressure(kinked, {0.0, -3.0}, {10.0, -3.0}).force ==
        Approx(10.0 * 3.0 - 0.5 * 10.0 * 2.0).epsilon(1e-13));  // 3 over 10 m less the dip's triangle
}

TEST_CASE("a dry line and a fill are checked where they are read", "[water][input]") {
  const std::string blocks =
      R"("control": {"time_step": 0.01, "steps": 1},
         "materials": {"rock": {"model": "elastic", "density": 2500, "young": 1e9, "poisson": 0.25}},
         "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
         "blocks": [{"vertices": [[0,0],[1,0],[1,1],[0,1]], "material": "rock"}])";
  auto scene = [&](const std::string& water, const std::string& random = "") {
    std::string text = "{" + blocks + ", \"water\": " + water;
    if (!random.empty()) {
      text += R"(, "random_strengths": {"variables": [)";
      text += random;
      text += "]}";
    }
    text += "}";
    return text;
  };
  const std::string both = R"({"phreatic_line": [[0, 2], [5, 3]], "dry_line": [[0, 0], [5, 0]], "fill": 0.25})";
  CHECK(parse_scene_text(scene(both), "s.json").water->fill == 0.25);
  CHECK_THROWS_WITH(parse_scene_text(scene(R"({"phreatic_line": [[0, 2], [5, 3]], "fill": 0.5})"), "s.json"),
                    Catch::Contains("s.json: water.fill: needs \"dry_line\""));
  CHECK_THROWS_WITH(parse_scene_text(scene(R"({"phreatic_line": [[0, 2], [5, 3]], "dry_line": [[0, 0], [5, 0]], "fill": 1.5})"), "s.json"),
                    Catch::Contains("water.fill"));
  CHECK_THROWS_WITH(parse_scene_text(scene(R"({"phreatic_line": [[0, 2], [5, 3]], "dry_line": [[1, 0], [0, 0]]})"), "s.json"),
                    Catch::Contains("water.dry_line[1]: x must increase along the dry line"));
  const std::string fill = R"({"water": "fill", "distribution": "normal", "mean": 0.5, "standard_deviation": 0.1})";
  const Scene drawn = parse_scene_text(scene(both, fill), "s.json");
  REQUIRE(drawn.random_strengths.variables.size() == 1);
  CHECK(drawn.random_strengths.variables[0].owner == StrengthOwner::Water);
  CHECK(drawn.random_strengths.variables[0].max == 1.0);
  CHECK_THROWS_WITH(parse_scene_text(scene(R"({"phreatic_line": [[0, 2], [5, 3]]})", fill), "s.json"),
                    Catch::Contains("random_strengths.variables[0].water: the scene's \"water\" has no \"dry_line\""));
  CHECK_THROWS_WITH(parse_scene_text(scene(both, R"({"water": "level", "distribution": "normal", "mean": 0.5, "standard_deviation": 0.1})"), "s.json"),
                    Catch::Contains("unknown water property \"level\""));
  // N(0.5, 0.3) reaches beyond 1 with probability 0.048: the bound must be given.
  CHECK_THROWS_WITH(parse_scene_text(scene(both, R"({"water": "fill", "distribution": "normal", "mean": 0.5, "standard_deviation": 0.3, "min": 0})"), "s.json"),
                    Catch::Contains("exceeds 1"));
  CHECK_THROWS_WITH(parse_scene_text(scene(both, R"({"water": "fill", "property": "fill", "distribution": "normal", "mean": 0.5, "standard_deviation": 0.1})"), "s.json"),
                    Catch::Contains("random_strengths.variables[0].property"));
}
