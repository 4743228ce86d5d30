// The settling after a consolidation (studies/settle_to_rest.hpp): the pace read from a
// made-up geometric decay, a rigid block on soft contact springs whose static steps relax at
// a closed-form pace, a block on a slope that never settles, and consolidate() putting such
// a settling back.
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>

#include "io/scene_reader.hpp"
#include "solver/run.hpp"
#include "studies/settle_to_rest.hpp"
#include "studies/strength_reduction.hpp"

namespace {

using namespace dda;
using json = nlohmann::json;

// A rigid 1 m square of density 2500 (m = 2500 kg/m) on a fixed base, on two vertex contacts
// of penalty p, one static step of gravity before the settling. `slope_deg` tilts gravity
// (a frictionless joint: no rest once tilted).
Scene block_on_springs_scene(double penalty, double dt, double slope_deg, double friction_deg) {
  const double g = 9.81, a = slope_deg * M_PI / 180.0;
  json scene = {
      {"gravity", {g * std::sin(a), -g * std::cos(a)}},
      {"control",
       {{"time_step", dt}, {"steps", 1}, {"dynamic_coefficient", 0.0}, {"penalty", penalty},
        {"allowed_penetration", 0.1}, {"max_augmentations", 0}, {"max_displacement_ratio", 0.1}}},
      {"materials",
       {{"rock", {{"model", "elastic"}, {"density", 2500.0}, {"young", 1e10}, {"poisson", 0.25},
                  {"rigid", true}}}}},
      {"joint_materials", {{"default", {{"friction_angle", friction_deg}, {"cohesion", 0.0}, {"tensile_strength", 0.0}}}}},
      {"blocks",
       {{{"vertices", {{-3.0, -1.0}, {3.0, -1.0}, {3.0, 0.0}, {-3.0, 0.0}}}, {"material", "rock"}, {"fixed", true}},
        {{"vertices", {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}}, {"material", "rock"}}}},
  };
  return parse_scene_text(scene.dump(), "block on springs");
}

World block_on_springs(double penalty, double dt, double slope_deg, double friction_deg) {
  World w = make_world(block_on_springs_scene(penalty, dt, slope_deg, friction_deg));
  const RunStats stats = run(w, [](const World&, const RunStats&) { return true; });
  REQUIRE_FALSE(stats.diverged);
  return w;
}

TEST_CASE("the relaxation's pace from a geometric decay", "[studies][settle]") {
  // r_n = r0 rho^n falls by e in -1 / ln(rho) steps; the windows' means fall at the same pace.
  const double rho = 0.99;
  std::vector<double> r;
  for (int n = 0; n < 400; ++n) r.push_back(0.3 * std::pow(rho, n));
  CHECK(relaxation_steps_of(r) == Approx(-1.0 / std::log(rho)).epsilon(1e-12));
  // Too few steps to read a pace from, or a ratio that does not fall: none.
  CHECK(relaxation_steps_of(std::vector<double>(r.begin(), r.begin() + 50)) == 0.0);
  CHECK(relaxation_steps_of(std::vector<double>(200, 1e-3)) == 0.0);
  // The unbalanced ratio: a block with an out-of-balance acceleration a moves a dt^2 / 2 in a
  // static step, read as a / g.
  CHECK(unbalanced_ratio(0.5 * 0.3 * 9.81 * 1e-4, 9.81, 0.01) == Approx(0.3).epsilon(1e-14));
}

TEST_CASE("a block on soft springs settles at the static step's pace", "[studies][settle]") {
  // Its vertical mode: stiffness K = 2 p (two vertex contacts), mass m. A static step solves
  // (K + 2 m / dt^2) d = r and leaves r / (1 + K dt^2 / (2 m)) out of balance: the force falls
  // by e in 1 / ln(1 + p dt^2 / m) steps, 100.5 here.
  const double p = 1e6, dt = 0.005, m = 2500.0;
  World w = block_on_springs(p, dt, 0.0, 30.0);
  const Settling s = settle_to_rest(w, SettlingSettings{});
  CHECK(s.at_rest);
  CHECK(s.stopped == "at rest");
  const double rho = 1.0 / (1.0 + p * dt * dt / m);
  const double expected = -1.0 / std::log(rho);
  // Measured 100.49917079 against 100.49917081: the decay is geometric to round-off (the
  // contacts stay closed, the block is rigid); 1e-6 leaves room for the solver's round-off.
  CHECK(s.relaxation_steps == Approx(expected).epsilon(1e-6));
  // The consolidation's one step left rho of the weight out of balance, so the settling's
  // first step moves the block rho^2 of a free fall's step.
  CHECK(s.unbalanced_start == Approx(rho * rho).epsilon(1e-6));
  CHECK(s.unbalanced_end < SettlingSettings{}.rest_ratio);
  // To below 2e-5 in ln(rho^2 / 2e-5) e-folds, read over the last 20 steps' mean, which
  // lags the step by 9.5 steps: 1094.9 (measured 1097; 3 for whole steps and the window
  // mean of a geometric series, which is not its midpoint's value).
  CHECK(std::abs(s.steps - (expected * std::log(rho * rho / 2e-5) + 9.5)) < 3.0);
  // The trial time follows: 20 e-folds of that pace at the trial's step, when longer than
  // the automatic one.
  FosSettings settings;
  const FosSettings resolved = resolve_fos_settings(w, settings, s.relaxation_steps);
  CHECK(resolved.trial_time ==
        Approx(std::max(resolve_fos_settings(w, settings).trial_time,
                        settings.relaxations_per_trial * s.relaxation_steps * dt)));
  CHECK(resolved.trial_time > resolve_fos_settings(w, settings).trial_time);
}

TEST_CASE("a block that cannot stand does not settle", "[studies][settle]") {
  // Gravity tilted 20 degrees over a joint of 10 degrees: the block slides at a steady
  // unbalanced force, g (sin 20 - cos 20 tan 10) = 0.177 g, and the creep test ends the
  // settling after its three windows of 50 steps that do not fall.
  World w = block_on_springs(1e9, 0.01, 20.0, 10.0);
  const Settling s = settle_to_rest(w, SettlingSettings{});
  CHECK_FALSE(s.at_rest);
  CHECK(s.stopped == "not settling");
  CHECK(s.steps == 200);  // the first window sets the level, three more do not fall below it
  CHECK(s.relaxation_steps == 0.0);
  CHECK(s.unbalanced_end == Approx(std::sin(0.349066) - std::cos(0.349066) * std::tan(0.174533)).epsilon(0.02));
}

TEST_CASE("a consolidation that does not settle is put back where the scene's run left it",
          "[studies][settle]") {
  // The block of the case above: the settling creeps 200 static steps at 0.177 g, moving it
  // 200 x 0.177 g dt^2 / 2 = 0.017 m down the joint, then stops "not settling". consolidate()
  // hands the trials the block where the scene's own run (one static step) left it, exactly.
  const Scene scene = block_on_springs_scene(1e9, 0.01, 20.0, 10.0);
  const Consolidation c = consolidate(scene, 1.0, [](const World&, const RunStats&) { return true; });
  CHECK(c.settling.stopped == "not settling");
  CHECK(c.settling.steps == 200);
  CHECK_FALSE(c.settling.kept);
  const World scene_end = block_on_springs(1e9, 0.01, 20.0, 10.0);
  CHECK(c.world.blocks[1].moments.centroid == scene_end.blocks[1].moments.centroid);
  CHECK(c.world.time == scene_end.time);
  // Without the put-back the block would be that far down: the settling did move it.
  World settled = block_on_springs(1e9, 0.01, 20.0, 10.0);
  (void)settle_to_rest(settled, SettlingSettings{});
  const double moved = (settled.blocks[1].moments.centroid - scene_end.blocks[1].moments.centroid).norm();
  // The creep moves a dt^2 / 2 a step from rest at a = 0.177 g: measured 2.4e-6 from that
  // closed form (the springs' own settling in the first steps); bound four times that.
  const double a = 9.81 * (std::sin(0.349066) - std::cos(0.349066) * std::tan(0.174533));
  CHECK(moved == Approx(200 * 0.5 * a * 1e-4).epsilon(1e-5));
}

}  // namespace
