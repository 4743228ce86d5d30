// Barton-Bandis joints (JointLaw jrc, jcs; law_at_stress; docs/scene-format.md,
// joint_materials): the friction angle phi_r + JRC log10(JCS / sigma_n) and its bounds, and
// a direct shear test through the run loop, a block on a fixed base under a constant normal
// load, pushed along the joint by a pin whose anchor moves at a constant rate: each sliding
// contact resists with N tan(phi_r + JRC log10(JCS L / N)) at its normal stress, so that
// the peak shear stress falls relative to the normal stress as the normal load grows.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "contact/joint_law.hpp"
#include "io/scene_reader.hpp"
#include "solver/moving_anchors.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"
#include "studies/strength_reduction.hpp"
#include "support/input_refusal.hpp"

using namespace dda;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kPhiR = 30.0, kJrc = 10.0, kJcs = 50e6;  // degrees, -, Pa

double rad(double deg) { return deg * M_PI / 180.0; }

// A 2 m x 0.5 m rigid block on a fixed base (wide and low, so that the pin's push at its
// side's mid-height cannot tip it over even at a friction angle near 70 degrees), loaded down
// by `load` N/m at its top centre, with a pin at its left side's mid-height that the test
// drags along +x; static steps (quasi-static shear).
nlohmann::json shear_box(double load) {
  nlohmann::json s = nlohmann::json::parse(R"({
    "gravity": [0.0, -9.81],
    "control": {"time_step": 0.01, "steps": 120, "dynamic_coefficient": 0.0},
    "materials": {"rock": {"model": "elastic", "density": 2500, "young": 1e10, "poisson": 0.25, "rigid": true}},
    "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0,
                                    "jrc": 10, "jcs": 5e7}},
    "blocks": [
      {"vertices": [[-4, -1], [4, -1], [4, 0], [-4, 0]], "material": "rock", "fixed": true},
      {"vertices": [[-1, 0], [1, 0], [1, 0.5], [-1, 0.5]], "material": "rock"}
    ],
    "pins": [{"point": [-1.0, 0.25]}]
  })");
  s["point_loads"] = {{{"point", {0.0, 0.5}}, {"force", {0.0, -load}}}};
  return s;
}

}  // namespace

TEST_CASE("Barton-Bandis: the friction angle and its bounds", "[joint][barton_bandis]") {
  // JRC 10, JCS 50 MPa, phi_r 30: at sigma_n = 50 kPa, 30 + 10 x 3 = 60 degrees (log10 of
  // 1000 is 3 to the last bit).
  CHECK(barton_bandis_angle(kPhiR, kJrc, kJcs, 5e4) == Approx(60.0).epsilon(1e-14));
  CHECK(barton_bandis_angle(kPhiR, kJrc, kJcs, 5e6) == Approx(40.0).epsilon(1e-14));
  CHECK(barton_bandis_angle(kPhiR, kJrc, kJcs, 5e7) == kPhiR);   // at JCS: phi_r
  CHECK(barton_bandis_angle(kPhiR, kJrc, kJcs, 1e8) == kPhiR);   // beyond: phi_r, not below
  CHECK(barton_bandis_angle(kPhiR, kJrc, kJcs, 5e2) == 70.0);    // 80 bounded at 70
  CHECK(barton_bandis_angle(kPhiR, kJrc, kJcs, 0.0) == 70.0);
  JointLaw law{std::tan(rad(kPhiR)), 0.0, 0.0, JointLawKind::BrittleBond};
  law.jrc = kJrc;
  law.jcs = kJcs;
  // A contact of 0.5 m carrying 25 kN/m: 50 kPa, 60 degrees; a trial at F = 2 halves it.
  CHECK_THAT(law_at_stress(law, 2.5e4, 0.5).tan_phi, WithinRel(std::tan(rad(60.0)), 1e-14));
  CHECK_THAT(law_at_stress(reduced_joint_law(law, 2.0), 2.5e4, 0.5).tan_phi,
             WithinRel(0.5 * std::tan(rad(60.0)), 1e-14));
  CHECK(law_at_stress(law, 2.5e4, 0.0).tan_phi == Approx(std::tan(rad(kPhiR))));  // a point: phi_r
  // A Coulomb law is left as it is.
  JointLaw coulomb{0.7, 0.0, 0.0, JointLawKind::BrittleBond};
  CHECK(law_at_stress(coulomb, 2.5e4, 0.5).tan_phi == 0.7);
}

TEST_CASE("Barton-Bandis: a direct shear test's resistance follows the law at each contact's "
          "normal stress",
          "[joint][barton_bandis]") {
  // Two normal loads a decade apart: the friction angle the joint mobilises falls from about
  // 50 to about 40 degrees as the normal stress grows tenfold (the law's curvature).
  std::vector<double> angles;
  for (const double load : {1e5, 1e6}) {
    World world = make_world(parse_scene_text(shear_box(load).dump(), "shear.json"));
    RunHook hook;
    hook.before_step = moving_anchors(Vec2(1e-4, 0.0));  // 1.2 cm over the run
    int checked = 0;
    double worst = 0.0, shear_sum = 0.0, normal_sum = 0.0;
    double steepest = 0.0, flattest = 90.0;  // the law's angles at the contacts' stresses
    hook.after_step = [&](const World& w, const RunStats&) {
      shear_sum = normal_sum = 0.0;
      steepest = 0.0;
      flattest = 90.0;
      for (const Contact& c : w.contacts) {
        if (c.state.mode == ContactMode::Open) continue;
        shear_sum += std::abs(c.iterate.shear_force);
        normal_sum += c.state.normal_force;
        const double own = barton_bandis_angle(kPhiR, kJrc, kJcs, c.state.normal_force / c.length);
        steepest = std::max(steepest, own);
        flattest = std::min(flattest, own);
        if (c.state.mode != ContactMode::Slide || c.start_normal_force <= 0.0) continue;
        // Each base contact stands for half the base (1 m); its friction is the law's at
        // the normal stress it started the step with.
        const double angle = barton_bandis_angle(kPhiR, kJrc, kJcs, c.start_normal_force / c.length);
        const double expected = c.state.normal_force * std::tan(rad(angle));
        worst = std::max(worst, std::abs(std::abs(c.iterate.shear_force) - expected) / expected);
        ++checked;
      }
      return true;
    };
    const RunStats stats = run(world, hook);
    REQUIRE_FALSE(stats.diverged);
    // Both contacts slide for most of the run (the pin loads the block over a few steps).
    CHECK(checked > 150);
    // The resistance is the law's to round-off (measured 1e-15; 1e-12 allows sums of a
    // few terms of 1e5-1e6 N).
    CHECK(worst < 1e-12);
    // The friction booked is what the joint resisted with over its slip: the account stays
    // closed (round-off on a scale of 1e4-1e5 J/m).
    CHECK(std::abs(world.energy.remainder) < 1e-6 * world.energy.scale);
    // At the end the whole base slides. The two contacts carry unequal normal forces (the
    // pin's push makes a moment), so the base's mobilised angle, atan(sum S / sum N), lies
    // between the law's angles at the two contacts' stresses (a weighted mean of their
    // tangents), not at the mean stress's (0.5 to 0.7 degree off it here, the law being
    // concave).
    const double mobilised = std::atan(shear_sum / normal_sum) * 180.0 / M_PI;
    INFO("load " << load << ": mobilised " << mobilised << ", the law between " << flattest
                 << " and " << steepest);
    CHECK(mobilised >= flattest - 1e-9);
    CHECK(mobilised <= steepest + 1e-9);
    CHECK(steepest - flattest > 0.1);  // the two stresses do differ
    angles.push_back(mobilised);
  }
  CHECK(angles[0] > angles[1] + 8.0);  // 10 log10(10) = 10 degrees less, up to the bound
}

TEST_CASE("Barton-Bandis: the reader's rules", "[joint][barton_bandis][input]") {
  const auto with = [](const nlohmann::json& keys) {
    nlohmann::json s = shear_box(1e5);
    nlohmann::json& j = s["joint_materials"]["default"];
    j.erase("jrc");
    j.erase("jcs");
    for (auto it = keys.begin(); it != keys.end(); ++it) j[it.key()] = it.value();
    return test::refusal_of([&] { parse_scene_text(s.dump(), "shear.json"); });
  };
  CHECK(with({{"jrc", 10}}).find("shear.json: joint_materials.default.jcs: required key is missing: "
                                 "a Barton-Bandis joint needs both") == 0);
  CHECK(with({{"jcs", 5e7}}).find("joint_materials.default.jrc: required key is missing") != std::string::npos);
  CHECK(with({{"jrc", 21}, {"jcs", 5e7}}).find("joint_materials.default.jrc: ") != std::string::npos);
  CHECK(with({{"jrc", 10}, {"jcs", 0}}).find("joint_materials.default.jcs: ") != std::string::npos);
  CHECK(with({{"jrc", 10}, {"jcs", 5e7}}) == "(accepted)");
}
