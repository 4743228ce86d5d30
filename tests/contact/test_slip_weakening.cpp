// A joint that falls from peak to residual strength as it slides (JointLaw residual_*,
// law_at_slip; docs/scene-format.md, joint_materials): the law's interpolation, and a direct
// shear test through the run loop, a block on a fixed base under a constant normal load,
// pushed along the joint by a pin whose anchor moves at a constant rate: the contacts' shear
// resistance against their slip follows c(s) L + N tan phi(s), peak to residual over
// residual_slip.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "contact/joint_law.hpp"
#include "io/scene_reader.hpp"
#include "solver/moving_anchors.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"
#include "support/input_refusal.hpp"

using namespace dda;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kPeakAngle = 35.0, kResidualAngle = 25.0;  // degrees
constexpr double kPeakCohesion = 2e4, kResidualCohesion = 0.0;  // Pa
constexpr double kResidualSlip = 0.01;                        // m

double rad(double deg) { return deg * M_PI / 180.0; }

// The closed form: at slip s, c(s) L + N tan(phi(s)), each linear from peak to residual.
double strength(double s, double normal, double length) {
  const double share = std::min(1.0, s / kResidualSlip);
  const double tan_phi = std::tan(rad(kPeakAngle)) + share * (std::tan(rad(kResidualAngle)) - std::tan(rad(kPeakAngle)));
  const double c = kPeakCohesion + share * (kResidualCohesion - kPeakCohesion);
  return c * length + normal * tan_phi;
}

// A 1 m rigid square on a fixed base (the joint along y = 0 bonded at the start: closed),
// loaded down by 50 kN/m at its top centre, with a pin at its left side's mid-height that
// the test drags along +x; static steps (quasi-static shear).
nlohmann::json shear_box() {
  return nlohmann::json::parse(R"({
    "gravity": [0.0, -9.81],
    "control": {"time_step": 0.01, "steps": 300, "dynamic_coefficient": 0.0},
    "materials": {"rock": {"model": "elastic", "density": 2500, "young": 1e10, "poisson": 0.25, "rigid": true}},
    "joint_materials": {"default": {"friction_angle": 35, "cohesion": 2e4, "tensile_strength": 2e4,
                                    "law": "coulomb_slip", "residual_friction_angle": 25,
                                    "residual_cohesion": 0, "residual_slip": 0.01}},
    "blocks": [
      {"vertices": [[-3, -1], [3, -1], [3, 0], [-3, 0]], "material": "rock", "fixed": true},
      {"vertices": [[-0.5, 0], [0.5, 0], [0.5, 1], [-0.5, 1]], "material": "rock"}
    ],
    "pins": [{"point": [-0.5, 0.5]}],
    "point_loads": [{"point": [0.0, 1.0], "force": [0.0, -5e4]}]
  })");
}

}  // namespace

TEST_CASE("slip weakening: the law falls linearly from peak to residual over residual_slip",
          "[joint][weakening]") {
  JointLaw law{0.7, 2e4, 1e4, JointLawKind::CoulombSlip};
  CHECK(law_at_slip(law, 5.0).tan_phi == law.tan_phi);  // no weakening given: the law itself
  law.residual_tan_phi = 0.5;
  law.residual_cohesion = 0.0;
  law.residual_slip = 0.01;
  CHECK(law_at_slip(law, 0.0).tan_phi == 0.7);
  CHECK_THAT(law_at_slip(law, 0.005).tan_phi, WithinAbs(0.6, 1e-15));
  CHECK_THAT(law_at_slip(law, 0.005).cohesion, WithinAbs(1e4, 1e-9));
  CHECK(law_at_slip(law, 0.02).tan_phi == 0.5);
  CHECK(law_at_slip(law, 0.02).cohesion == 0.0);
  CHECK(law_at_slip(law, 0.02).tensile_strength == 1e4);  // kept
}

TEST_CASE("slip weakening: a direct shear test's force against slip follows the closed form",
          "[joint][weakening]") {
  World world = make_world(parse_scene_text(shear_box().dump(), "shear.json"));
  const double rate = 1e-4;  // m a step: 0.03 m over 300 steps
  // Per accepted step, over the block's contacts on the base: the normal force they carry,
  // the shear they resist with, and how far they have slid (the two slide together).
  struct Point {
    double slip, normal, shear;
    bool sliding;
  };
  std::vector<Point> curve;
  RunHook hook;
  hook.before_step = moving_anchors(Vec2(rate, 0.0));
  hook.after_step = [&](const World& w, const RunStats&) {
    Point p{0.0, 0.0, 0.0, true};
    int n = 0;
    for (const Contact& c : w.contacts) {
      if (c.state.mode == ContactMode::Open) continue;
      p.normal += c.state.normal_force;
      p.shear += std::abs(c.iterate.shear_force);
      p.slip += c.state.slip_sum;
      p.sliding = p.sliding && c.state.mode == ContactMode::Slide;
      ++n;
    }
    if (n > 0) p.slip /= n;
    curve.push_back(p);
    return true;
  };
  const RunStats stats = run(world, hook);
  REQUIRE_FALSE(stats.diverged);
  REQUIRE(curve.back().slip > 2.0 * kResidualSlip);
  // While the contacts slide, the shear they resist with is the law at the slip the step
  // started with (the step's slip, at most 1e-4 m here, is added at its end): c(s) L +
  // N tan phi(s), L = 1 m (each of the base's two contacts carries half of it). The normal
  // force is the contacts' own (the pin holds the block a little too). Measured equal to
  // the closed form at the slip before the step to round-off (it passes at 1e-12): 1e-11.
  int checked = 0;
  double before = 0.0;  // the slip at the step's start
  for (const Point& p : curve) {
    if (p.sliding && p.normal > 0.0) {
      INFO("slip " << before << " normal " << p.normal << " shear " << p.shear);
      CHECK_THAT(p.shear, WithinRel(strength(before, p.normal, 1.0), 1e-11));
      ++checked;
    }
    before = p.slip;
  }
  CHECK(checked > 200);
  // From peak to residual: the resistance at the end is the residual's.
  const Point& last = curve.back();
  CHECK_THAT(last.shear, WithinRel(last.normal * std::tan(rad(kResidualAngle)), 1e-11));
  // The friction booked is what the joint resisted with over its slip: the account closed
  // (round-off of a scale of 1e5 J/m).
  CHECK(std::abs(world.energy.remainder) < 1e-6 * world.energy.scale);
}

TEST_CASE("slip weakening: the reader's rules", "[joint][weakening][input]") {
  const auto with = [](const nlohmann::json& keys) {
    nlohmann::json s = shear_box();
    nlohmann::json& j = s["joint_materials"]["default"];
    j.erase("residual_friction_angle");
    j.erase("residual_cohesion");
    j.erase("residual_slip");
    for (auto it = keys.begin(); it != keys.end(); ++it) j[it.key()] = it.value();
    return test::refusal_of([&] { parse_scene_text(s.dump(), "shear.json"); });
  };
  CHECK(with({{"residual_friction_angle", 20}}).find(
            "shear.json: joint_materials.default.residual_slip: required key is missing") == 0);
  CHECK(with({{"residual_friction_angle", 40}, {"residual_slip", 0.01}}).find(
            "shear.json: joint_materials.default.residual_friction_angle") == 0);
  CHECK(with({{"residual_cohesion", 3e4}, {"residual_slip", 0.01}}).find(
            "shear.json: joint_materials.default.residual_cohesion") == 0);
  CHECK(with({{"residual_slip", 0.0}}).find("shear.json: joint_materials.default.residual_slip") == 0);
  CHECK(with({{"residual_slip", 0.01}}) == "(accepted)");  // friction kept, cohesion to 0
}
