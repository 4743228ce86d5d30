// Excavation stages (solver/excavation.hpp; docs/scene-format.md, "stages"): a stack of three
// blocks on a fixed base, consolidated, then the upper two removed in two lifts or in one.
// The block left carries its own weight alone (its mean vertical stress -rho g h / 2), the two
// paths end in the same state, the energy account books what each removal took away and
// stays closed, a bolt into a removed block breaks, and the reader refuses a bad list.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "support/input_refusal.hpp"
#include "io/scene_reader.hpp"
#include "solver/energy.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"

using namespace dda;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kDensity = 2500.0, kG = 9.81;

// A fixed base and three 1 m squares stacked on it (blocks 1, 2, 3 from the bottom); a static
// stage of 0.5 s, then `lifts` (each a list of blocks removed at its start, 0.5 s each).
nlohmann::json stack_scene(const nlohmann::json& lifts) {
  nlohmann::json stages = nlohmann::json::array({{{"duration", 0.5}, {"dynamic_coefficient", 0.0}}});
  for (const auto& lift : lifts) {
    stages.push_back({{"duration", 0.5}, {"dynamic_coefficient", 0.0}, {"excavate", lift}});
  }
  nlohmann::json blocks = nlohmann::json::array(
      {{{"vertices", {{-2.0, -1.0}, {2.0, -1.0}, {2.0, 0.0}, {-2.0, 0.0}}}, {"material", "rock"}, {"fixed", true}}});
  for (int k = 0; k < 3; ++k) {
    const double y = k;
    blocks.push_back({{"vertices", {{-0.5, y}, {0.5, y}, {0.5, y + 1.0}, {-0.5, y + 1.0}}}, {"material", "rock"}});
  }
  return {{"gravity", {0.0, -kG}},
          {"control", {{"time_step", 0.01}}},
          {"materials", {{"rock", {{"model", "elastic"}, {"density", kDensity}, {"young", 1e9}, {"poisson", 0.25}}}}},
          {"joint_materials", {{"default", {{"friction_angle", 35}, {"cohesion", 0}, {"tensile_strength", 0}}}}},
          {"blocks", blocks},
          {"stages", stages}};
}

World run_scene(const nlohmann::json& scene) {
  World world = make_world(parse_scene_text(scene.dump(), "stack.json"));
  const RunStats stats = run(world, RunHook{});
  REQUIRE_FALSE(stats.diverged);
  return world;
}

std::string refusal(const nlohmann::json& scene) {
  return test::refusal_of([&] { parse_scene_text(scene.dump(), "stack.json"); });
}

}  // namespace

TEST_CASE("excavation: the block left carries its own weight alone, by two lifts or one, and "
          "the energy account books what the removals took",
          "[excavation]") {
  const World two = run_scene(stack_scene(nlohmann::json::array({{3}, {2}})));
  const World one = run_scene(stack_scene(nlohmann::json::array({{2, 3}})));
  for (const World* w : {&two, &one}) {
    CHECK(w->blocks[2].excavated);
    CHECK(w->blocks[3].excavated);
    CHECK_FALSE(w->blocks[1].excavated);
    CHECK(w->dof_count == 6);  // the one block left
    CHECK(w->contacts.size() > 0);
    for (const Contact& c : w->contacts) {
      CHECK(c.key.vertex_block != 2);
      CHECK(c.key.edge_block != 2);
      CHECK(c.key.vertex_block != 3);
      CHECK(c.key.edge_block != 3);
    }
    // The mean vertical stress of a block on its base under its own weight: -rho g h / 2
    // (DDA's constant stress is the mean of the linear one). That is the small-strain
    // closed form; the default treatment keeps the block's own change of shape, which moves
    // the stress by about its strain, |s| / E (1.2e-5 here; measured 1.04e-5): twice that.
    const double own = -kDensity * kG * 1.0 / 2.0;
    CHECK_THAT(w->blocks[1].stress[1], WithinRel(own, 2.0 * std::abs(own) / 1e9));
    // The account: what left with the blocks is booked; nothing else unexplained (round-off
    // of a scale of 1e5 J/m).
    CHECK(w->energy.excavation != 0.0);
    CHECK(std::abs(w->energy.remainder) < 1e-9 * w->energy.scale);
  }
  // Two lifts or one: the same end, the block left where it settled under its own weight
  // (its springs' compression m g / p differs from the loaded one's by far more than this).
  CHECK_THAT(two.blocks[1].moments.centroid.y(), WithinAbs(one.blocks[1].moments.centroid.y(), 1e-12));
  CHECK_THAT(two.blocks[1].stress[1], WithinRel(one.blocks[1].stress[1], 1e-9));
  // And the same as the slope built without them: the base and the bottom block alone (two
  // static stages, so that the steps are the same).
  nlohmann::json built = stack_scene(nlohmann::json::array({nlohmann::json::array()}));
  built["stages"][1].erase("excavate");
  built["blocks"].erase(3);
  built["blocks"].erase(2);
  const World alone = run_scene(built);
  // Not bit for bit: the multipliers (penetration control) its contacts grew while the block
  // carried the others stay while they stay closed, so it rests a little higher (measured
  // 4.6e-8 m, its stress 2.3e-6 apart). Bounded by how far the springs sank under the full
  // load, 3 m g / (2 p) with p = 50 E: 7.4e-7 m; the stress within 1e-5.
  const double sank = 3.0 * kDensity * kG / (2.0 * 50.0 * 1e9);
  CHECK_THAT(two.blocks[1].moments.centroid.y(), WithinAbs(alone.blocks[1].moments.centroid.y(), sank));
  CHECK_THAT(two.blocks[1].stress[1], WithinRel(alone.blocks[1].stress[1], 1e-5));
  // Before any lift the bottom block carried three blocks' weight: -2.5 rho g h.
  const World none = run_scene(stack_scene(nlohmann::json::array()));
  // (Measured 5.2e-5 off the small-strain value at a strain of 6.1e-5.)
  const double loaded = -2.5 * kDensity * kG;
  CHECK_THAT(none.blocks[1].stress[1], WithinRel(loaded, 2.0 * std::abs(loaded) / 1e9));
}

TEST_CASE("excavation: a bolt with an end in a removed block breaks, its spring energy booked",
          "[excavation][bolts]") {
  nlohmann::json scene = stack_scene(nlohmann::json::array({{3}}));
  scene["bolts"] = {{{"name", "B"}, {"from", {0.0, 1.5}}, {"to", {0.0, 2.5}}, {"stiffness", 1e8},
                     {"pretension", 1e4}}};
  const World w = run_scene(scene);
  REQUIRE(w.bolts.size() == 1);
  CHECK(w.bolts[0].broken);
  CHECK(w.bolts[0].force == 0.0);
  CHECK_THAT(w.bolts[0].broken_at, WithinAbs(0.5, 1e-9));
  CHECK(std::abs(w.energy.remainder) < 1e-9 * w.energy.scale);
}

TEST_CASE("excavation: the reader refuses a bad list at its place", "[excavation][input]") {
  CHECK(refusal(stack_scene(nlohmann::json::array({{7}}))).find(
            "stack.json: stages[1].excavate[0]: block 7 is out of range") == 0);
  CHECK(refusal(stack_scene(nlohmann::json::array({{3}, {3}}))).find(
            "stack.json: stages[2].excavate[0]: block 3 is excavated already") == 0);
  CHECK(refusal(stack_scene(nlohmann::json::array({nlohmann::json::array()}))).find(
            "stack.json: stages[1].excavate: ") == 0);
}
