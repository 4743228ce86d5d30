// The mode of a failing trial's mechanism (studies/trial_mechanism.hpp): the rule on made-up
// blocks, and the trials of two limit-equilibrium cases whose mechanism is known: Goodman and
// Bray's columns topple, Hoek and Bray's block slides.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "../../verification/slope/slope_cases.hpp"
#include "io/scene_reader.hpp"
#include "solver/run.hpp"
#include "studies/strength_reduction.hpp"
#include "studies/trial_mechanism.hpp"

namespace {

using namespace dda;

std::vector<BlockMotion> motions(const std::vector<std::string>& modes) {
  std::vector<BlockMotion> out;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    BlockMotion b;
    b.block = static_cast<int>(i);
    b.displacement = Vec2(-1e-3, 0.0);
    b.mode = modes[i];
    out.push_back(b);
  }
  return out;
}

const slope::SlopeCase& slope_case(const std::string& name) {
  static const std::vector<slope::SlopeCase> cases = slope::all_cases(0.002);
  for (const slope::SlopeCase& c : cases) {
    if (c.name == name) return c;
  }
  FAIL("no slope case " << name);
  return cases.front();
}

// The case consolidated as verification/slope consolidates it, and its trial at 1.1 times its
// limit-equilibrium factor: 10 % beyond it the mechanism fails clearly (the verdict's
// resolution is below 1 %).
TrialMechanism failing_mechanism_of(const slope::SlopeCase& c) {
  const Consolidation cons = consolidate(parse_scene_text(c.scene, c.name), c.le_factor < 1.05 ? 0.5 : 1.0,
                                         [](const World&, const RunStats&) { return true; });
  REQUIRE_FALSE(cons.stats.diverged);
  const FosSettings s = resolve_fos_settings(cons.world, FosSettings{});
  const TrialResult t = run_trial(cons.world, s, 1.1 * c.le_factor);
  REQUIRE_FALSE(t.stable);
  return trial_mechanism(cons.world, t.world, LimitAnalysisSettings{});
}

}  // namespace

TEST_CASE("a group's mode: toppling by its blocks or by its slip across the motion, else by "
          "most of its blocks",
          "[mechanism]") {
  const SlipDirections none{};
  CHECK(group_mode({}, none) == "none");
  CHECK(group_mode(motions({"toppling"}), SlipDirections{10, 0, 0}) == "toppling");
  CHECK(group_mode(motions({"sliding", "toppling", "toppling"}), none) == "toppling group");
  // By the slip: one way at least twice as often as the other, or both.
  CHECK(group_mode(motions({"sliding", "sliding", "sliding"}), SlipDirections{3, 6, 0}) ==
        "toppling group");
  CHECK(group_mode(motions({"sliding", "sliding", "sliding"}), SlipDirections{0, 1, 0}) ==
        "toppling group");
  CHECK(group_mode(motions({"sliding", "sliding", "sliding"}), SlipDirections{3, 5, 0}) ==
        "sliding and toppling group");
  CHECK(group_mode(motions({"sliding", "sliding", "sliding"}), SlipDirections{8, 4, 9}) ==
        "sliding group");
  CHECK(group_mode(motions({"sliding", "sliding", "sliding"}), SlipDirections{0, 0, 2}) ==
        "sliding group");
  CHECK(group_mode(motions({"rotating", "rotating", "sliding"}), SlipDirections{1, 4, 0}) ==
        "rotating group");
  CHECK(group_mode(motions({"falling", "falling", "sliding"}), none) == "falling group");
  // Half is not most: two toppling of four is not a toppling group.
  CHECK(group_mode(motions({"toppling", "toppling", "sliding", "sliding"}), none) == "sliding group");
}

TEST_CASE("Goodman and Bray's columns fail as a toppling group, Hoek and Bray's block slides",
          "[mechanism]") {
  SECTION("toppling") {
    const TrialMechanism m = failing_mechanism_of(slope_case("toppling"));
    INFO("slip along " << m.slip.along << ", across " << m.slip.across);
    CHECK(m.mode == "toppling group");
    // The columns slip on each other's sides, which stand across their motion (they lean out
    // of the slope); the toe columns slide on their steps, along it.
    CHECK(m.slip.across >= 2 * m.slip.along);
    // The tall columns behind the toe tip on their toes: the tabular method has its upper
    // columns toppling at the limit, and at least the two tallest moving ones must do so here.
    long toppling = 0;
    for (const BlockMotion& b : m.blocks) toppling += b.mode == "toppling" ? 1 : 0;
    CHECK(toppling >= 2);
  }
  SECTION("planar sliding") {
    const TrialMechanism m = failing_mechanism_of(slope_case("planar_c10"));
    CHECK(m.mode == "sliding");
    CHECK(m.slip.across == 0);
  }
}
