// The factor over the time step and the penalty (studies/settings_spread.hpp): the settings
// reach the steps a trial runs (a stage carries its own copy of the time steps), and the
// spread is judged on made-up factors.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "io/scene_reader.hpp"
#include "studies/settings_spread.hpp"
#include "solver/world.hpp"

namespace {

using namespace dda;
using json = nlohmann::json;

// A block on a fixed base, consolidated by a static stage that gives no time step of its own
// (the reader copies control's into it).
std::string staged_scene(const json& penalty) {
  json control = {{"time_step", 0.01}};
  if (!penalty.is_null()) control["penalty"] = penalty;
  return json{
      {"control", control},
      {"joint_materials", {{"default", {{"friction_angle", 30.0}, {"cohesion", 0.0}, {"tensile_strength", 0.0}}}}},
      {"materials", {{"rock", {{"model", "elastic"}, {"density", 2500.0}, {"young", 1e9}, {"poisson", 0.25}}}}},
      {"blocks",
       {{{"vertices", {{-5, -1}, {5, -1}, {5, 0}, {-5, 0}}}, {"material", "rock"}, {"fixed", true}},
        {{"vertices", {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, {"material", "rock"}}}},
      {"stages", {{{"duration", 0.05}, {"dynamic_coefficient", 0.0}, {"gravity_ramp", {0.0, 1.0}}}}}}
      .dump();
}

SpreadFactor found_at(const char* setting, double factor) {
  SpreadFactor f;
  f.setting = setting;
  f.found = true;
  f.factor = factor;
  // A bracket 0.006 wide about it, as a search to the default tolerance leaves.
  f.last_stable = factor - 0.003;
  f.first_failing = factor + 0.003;
  return f;
}

}  // namespace

TEST_CASE("a spread setting scales the stages' time steps, which the trials run on", "[fos][spread]") {
  const Scene scene = parse_scene_text(staged_scene(nullptr), "staged");
  REQUIRE(scene.stages.size() == 1);
  REQUIRE(scene.stages[0].time_steps == std::vector<double>{0.01});
  const Scene fine = with_spread_setting(scene, kSpreadSettings[0]);  // dt / 5
  CHECK(fine.control.time_steps[0] == Approx(0.002).epsilon(1e-15));
  CHECK(fine.stages[0].time_steps[0] == Approx(0.002).epsilon(1e-15));
  // The consolidation ends on the stage's steps, and a trial takes the world's: scaling
  // control's alone left every trial at 0.01 s.
  const Consolidation c = consolidate(fine, 1.0, [](const World&, const RunStats&) { return true; });
  REQUIRE_FALSE(c.stats.diverged);
  CHECK(c.world.control.time_steps[0] == Approx(0.002).epsilon(1e-15));
  CHECK(c.stats.steps >= 25);  // 0.05 s at 0.002 s (cuts only add steps)
  CHECK(fine.control.penalty == scene.control.penalty);  // the penalty untouched
}

TEST_CASE("a spread setting scales the penalty, auto or given", "[fos][spread]") {
  // "auto" is 50 x the largest Young's modulus (solver/world.hpp, resolve_penalty).
  const Scene automatic = parse_scene_text(staged_scene(nullptr), "auto");
  const Scene soft = with_spread_setting(automatic, kSpreadSettings[2]);  // penalty / 10
  REQUIRE(soft.control.penalty.has_value());
  CHECK(*soft.control.penalty == Approx(5e9).epsilon(1e-15));
  CHECK(soft.control.time_steps == automatic.control.time_steps);
  const Scene given = parse_scene_text(staged_scene(3e10), "given");
  const Scene stiff = with_spread_setting(given, kSpreadSettings[3]);  // penalty x 10
  CHECK(*stiff.control.penalty == Approx(3e11).epsilon(1e-15));
}

TEST_CASE("the spread of the factor over the settings is judged against 2 %", "[fos][spread]") {
  // Within: 1.000 to 1.015 about a mean of 1.006 is 1.49 %.
  const SettingsSpread close = judge_spread(
      1.0, 0.004, {found_at("dt/5", 1.005), found_at("dt*5", 1.015), found_at("penalty/10", 1.0),
            found_at("penalty*10", 1.01)});
  CHECK(close.computed);
  CHECK(close.within);
  CHECK(close.spread == Approx(0.015 / 1.006).epsilon(1e-12));
  CHECK_THAT(close.text, Catch::Contains("holds within 1.49 %"));
  // Known to the widest bracket over the mean: the settings' 0.006 (the search's 0.004).
  CHECK(close.resolution == Approx(0.006 / 1.006).epsilon(1e-12));
  CHECK_THAT(close.text, Catch::Contains("the spread is known to 0.60 %"));
  // Beyond: a tenth of the penalty gives 0.95; the text names the settings at both ends.
  const SettingsSpread apart = judge_spread(
      1.0, 0.004, {found_at("dt/5", 1.0), found_at("dt*5", 1.0), found_at("penalty/10", 0.95),
            found_at("penalty*10", 1.01)});
  CHECK_FALSE(apart.within);
  CHECK(apart.spread == Approx(0.06 / 0.992).epsilon(1e-12));
  CHECK_THAT(apart.text, Catch::Contains("lowest at penalty/10, highest at penalty*10"));
  CHECK_THAT(apart.text, Catch::Contains("plan with the lowest, F = 0.9500"));
  // Where the scene's own factor is an end, it is named (not a setting that ties it).
  const SettingsSpread tied = judge_spread(
      1.0, 0.004, {found_at("dt/5", 1.0), found_at("dt*5", 1.0), found_at("penalty/10", 0.95),
            found_at("penalty*10", 0.99)});
  CHECK_THAT(tied.text, Catch::Contains("lowest at penalty/10, highest at the scene's settings"));
  // A setting with no factor is not within, whatever the others say.
  SpreadFactor none;
  none.setting = "dt*5";
  none.message = "no trial failed up to F = 10";
  const SettingsSpread missing = judge_spread(
      1.0, 0.004, {found_at("dt/5", 1.0), none, found_at("penalty/10", 1.0), found_at("penalty*10", 1.0)});
  CHECK_FALSE(missing.within);
  CHECK(missing.spread == 0.0);
  CHECK_THAT(missing.text, Catch::Contains("no factor found at dt*5"));
}
