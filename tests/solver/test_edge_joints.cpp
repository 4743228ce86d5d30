// A contact takes the joint material of the edge it lies on (BlockSpec::edge_joints,
// joint_of_contact), before its pair's ("joints"): a block on a floor under gravity tilted by
// 20 degrees, the pair frictionless, the floor's top edge a 30-degree joint. With the edge's
// material the block holds (tan 30 > tan 20); without it the pair's frictionless joint lets
// it slide at g sin 20, the closed form.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "io/scene_reader.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"

using namespace dda;

namespace {

constexpr double kG = 9.81, kTilt = 20.0 * 3.14159265358979323846 / 180.0;

nlohmann::json floor_scene(bool edge_joints) {
  nlohmann::json floor = {{"vertices", {{-1.0, 0.0}, {10.0, 0.0}, {10.0, 1.0}, {-1.0, 1.0}}},
                          {"material", "rock"},
                          {"fixed", true}};
  // Edge 2 runs from (10, 1) to (-1, 1): the floor's top.
  if (edge_joints) floor["edge_joints"] = {nullptr, nullptr, "rough", nullptr};
  return {{"gravity", {kG * std::sin(kTilt), -kG * std::cos(kTilt)}},
          {"control", {{"time_step", 0.001}, {"steps", 200}}},
          {"materials",
           {{"rock", {{"model", "elastic"}, {"density", 2500.0}, {"young", 1e9}, {"poisson", 0.25}}}}},
          {"joint_materials",
           {{"default", {{"friction_angle", 0.0}, {"cohesion", 0.0}, {"tensile_strength", 0.0}}},
            {"smooth", {{"friction_angle", 0.0}, {"cohesion", 0.0}, {"tensile_strength", 0.0}}},
            {"rough", {{"friction_angle", 30.0}, {"cohesion", 0.0}, {"tensile_strength", 0.0}}}}},
          {"blocks",
           {floor, {{"vertices", {{1.0, 1.0}, {2.0, 1.0}, {2.0, 2.0}, {1.0, 2.0}}}, {"material", "rock"}}}},
          {"joints", {{{"blocks", {0, 1}}, {"material", "smooth"}}}}};
}

}  // namespace

TEST_CASE("a contact acts with the joint material of the edge it lies on, before its pair's",
          "[contact][joints]") {
  for (const bool edge_joints : {true, false}) {
    const Scene scene = parse_scene_text(floor_scene(edge_joints).dump(), "floor.json");
    REQUIRE(scene.warnings.empty() == edge_joints);  // without them "rough" is unused
    World world = make_world(scene);
    const int rough = 1, smooth = 2;  // "default", then the others by name
    REQUIRE(scene.joint_materials[static_cast<std::size_t>(rough)].name == "rough");
    bool every_contact_expected = true;
    int contacts_seen = 0;
    const RunStats stats = run(world, [&](const World& w, const RunStats&) {
      for (const Contact& c : w.contacts) {
        ++contacts_seen;
        const bool on_top = c.key.edge_block == 0 && c.key.edge == 2;
        every_contact_expected = every_contact_expected && on_top && c.joint == (edge_joints ? rough : smooth);
      }
      return true;
    });
    REQUIRE_FALSE(stats.diverged);
    CHECK(contacts_seen > 0);
    CHECK(every_contact_expected);
    const double moved = world.blocks[1].vertices[0].x() - 1.0;
    const double t = world.time;
    if (edge_joints) {
      // Held by friction: what moves is the shear springs' stretch under m g sin 20 (8.4 kN/m
      // on two springs of p / 2.5 = 2e10 N/m: 0.2 um) and the step's creep; 1 um bounds it,
      // 1e-4 of the 7 cm the frictionless block slides.
      CHECK(std::abs(moved) < 1e-6);
    } else {
      // Frictionless: x = g sin 20 t^2 / 2 (6.7 cm at 0.2 s). Implicit steps lag the
      // closed form by about one step's share (dt / t = 0.5 %): 1 % allows that.
      const double expected = 0.5 * kG * std::sin(kTilt) * t * t;
      CHECK(std::abs(moved - expected) < 0.01 * expected);
    }
  }
}
