// studies/consolidation_bonds: a bond's demand on its strength, and the broken bonds of a
// consolidation against an elastic solution, on a block hanging from a fixed one by a
// bonded joint (its weight is the joint's tension, a closed form).
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "io/scene_reader.hpp"
#include "studies/consolidation_bonds.hpp"
#include "studies/strength_reduction.hpp"

namespace {

using namespace dda;
using json = nlohmann::json;

// A 4 m x 1 m block hanging under a fixed block by a brittle bond of tensile strength (and
// cohesion) T: its weight W = 2500 x 9.81 x 4 = 98.1 kN per metre pulls on 4 m of joint, so
// every bonded contact carries W / (4 T) of its strength. Gravity ramps up over a static
// stage.
std::string hanging_scene(double tensile_strength) {
  json blocks = json::array();
  blocks.push_back({{"vertices", {{0, 0}, {4, 0}, {4, 2}, {0, 2}}}, {"material", "rock"}, {"fixed", true}});
  blocks.push_back({{"vertices", {{0, -1}, {4, -1}, {4, 0}, {0, 0}}}, {"material", "rock"}});
  const json scene = {
      {"gravity", {0.0, -9.81}},
      {"control", {{"time_step", 0.002}, {"max_displacement_ratio", 0.001}}},
      {"materials", {{"rock", {{"model", "elastic"}, {"density", 2500.0}, {"young", 1e10},
                               {"poisson", 0.25}, {"rigid", true}}}}},
      {"joint_materials",
       {{"default", {{"friction_angle", 30.0}, {"cohesion", tensile_strength},
                     {"tensile_strength", tensile_strength}, {"law", "brittle_bond"}}}}},
      {"blocks", blocks},
      {"stages", {{{"duration", 0.1}, {"dynamic_coefficient", 0.0}, {"gravity_ramp", {0.0, 1.0}}}}},
  };
  return scene.dump();
}

constexpr double kWeight = 2500.0 * 9.81 * 4.0;  // N per metre
constexpr double kLength = 4.0;                   // m of joint

}  // namespace

TEST_CASE("a bond's demand: tension over tensile strength, shear over Coulomb strength",
          "[fos][bonds]") {
  JointLaw law;
  law.tan_phi = 0.5;
  law.cohesion = 1000.0;
  law.tensile_strength = 2000.0;
  // 1000 N of tension on 0.5 m of a 2 kPa joint: its whole strength.
  CHECK(bond_demand(-1000.0, 0.0, 0.5, law) == Approx(1.0).epsilon(1e-15));
  // 600 N of shear under 400 N of compression: 600 / (1000 x 0.5 + 0.5 x 400) = 6/7.
  CHECK(bond_demand(400.0, -600.0, 0.5, law) == Approx(6.0 / 7.0).epsilon(1e-15));
  // In tension the shear strength is the cohesion alone: 400 / 500, above 200 / 1000.
  CHECK(bond_demand(-200.0, 400.0, 0.5, law) == Approx(0.8).epsilon(1e-15));
  // Nothing carried, nothing asked; tension on a joint without tensile strength, all of it.
  CHECK(bond_demand(0.0, 0.0, 0.5, law) == 0.0);
  law.tensile_strength = 0.0;
  CHECK(std::isinf(bond_demand(-1.0, 0.0, 0.5, law)));
}

TEST_CASE("a hanging block's bond breaks where the elastic solution overstresses it, and the "
          "check says so",
          "[fos][bonds]") {
  SECTION("strength W / (4 m x 2.45): the consolidation breaks every bond, each explained") {
    const Scene scene = parse_scene_text(hanging_scene(kWeight / kLength / 2.45), "hanging");
    const Consolidation c = consolidate(scene, 1.0, [](const World&, const RunStats&) { return true; });
    REQUIRE(c.stats.bonds_broken > 0);
    const BondCheck check = check_consolidation_bonds(scene, 1.0, c.stats.broken_bonds);
    REQUIRE(check.computed);
    CHECK(check.broken == c.stats.bonds_broken);
    CHECK(check.explained == check.broken);
    CHECK(check.unexplained.empty());
    // The elastic solution holds the block, every bond at 2.45 times its strength.
    CHECK(check.bonded_elastic >= 2);
    CHECK(check.overstressed_elastic == check.bonded_elastic);
  }
  SECTION("demand 0.8 (W / (4 m x 0.8)): nothing breaks, nothing is overstressed") {
    const Scene scene = parse_scene_text(hanging_scene(kWeight / kLength / 0.8), "hanging");
    const Consolidation c = consolidate(scene, 1.0, [](const World&, const RunStats&) { return true; });
    CHECK(c.stats.bonds_broken == 0);
    const BondCheck check = check_consolidation_bonds(scene, 1.0, c.stats.broken_bonds);
    REQUIRE(check.computed);
    CHECK(check.broken == 0);
    CHECK(check.bonded_elastic >= 2);
    CHECK(check.overstressed_elastic == 0);
  }
  SECTION("demand 1.25 at the consolidation's factor 0.5 is 0.625: the check reads the "
          "strengths the consolidation used") {
    const Scene scene = parse_scene_text(hanging_scene(kWeight / kLength / 1.25), "hanging");
    const BondCheck check = check_consolidation_bonds(scene, 0.5, {});
    REQUIRE(check.computed);
    CHECK(check.overstressed_elastic == 0);
    const BondCheck full = check_consolidation_bonds(scene, 1.0, {});
    CHECK(full.overstressed_elastic == full.bonded_elastic);
  }
}
