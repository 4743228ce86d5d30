// Rigid-block limit analysis (studies/limit_analysis.hpp) against closed forms: a block on a
// plane (friction alone, with cohesion, with an uplift, Barton-Bandis), a block that can only topple, two
// blocks on a plane that share their friction, the slope verification's limit-equilibrium
// cases; and the CLI's --method limit-analysis.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "../../verification/slope/slope_cases.hpp"
#include "contact/joint_law.hpp"
#include "io/scene_reader.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"
#include "studies/limit_analysis.hpp"
#include "studies/strength_reduction.hpp"
#include "studies/trial_mechanism.hpp"
#include "support/cli_helpers.hpp"

namespace {

using namespace dda;
using json = nlohmann::json;

constexpr double kPi = 3.14159265358979323846;
double deg(double d) { return d * kPi / 180.0; }

// The bisection's resolution (LimitAnalysisSettings::relative_tolerance): the factor
// returned is the bracket's admissible end, at most this share below the true one.
constexpr double kBracket = 1e-3;

// Blocks on a fixed plane at `dip` degrees: each a rectangle `width` along the plane and
// `height` across it, side by side from s = 5 m up the plane, touching; a static stage
// ramps gravity up so that every contact is closed (and bonded, with cohesion) at its end.
struct OnPlane {
  double dip = 30.0, phi = 35.0, cohesion = 0.0;
  std::vector<double> widths{10.0};
  double height = 4.0;
  std::string scene_text() const {
    const Vec2 t(std::cos(deg(dip)), std::sin(deg(dip))), n(-t.y(), t.x());
    auto at = [&](double s, double q) {
      const Vec2 p = s * t + q * n;
      return json::array({p.x(), p.y()});
    };
    json blocks = json::array();
    blocks.push_back({{"vertices", {at(-10, 0), at(-10, -3), at(40, -3), at(40, 0)}},
                      {"material", "rock"}, {"fixed", true}});
    double s = 5.0;
    for (double w : widths) {
      blocks.push_back({{"vertices", {at(s, 0), at(s + w, 0), at(s + w, height), at(s, height)}},
                        {"material", "rock"}});
      s += w;
    }
    json scene = {
        {"gravity", {0.0, -9.81}},
        {"control", {{"time_step", 0.002}, {"max_displacement_ratio", 0.001}}},
        {"materials", {{"rock", {{"model", "elastic"}, {"density", 2500.0}, {"young", 1e10},
                                 {"poisson", 0.25}, {"rigid", true}}}}},
        {"joint_materials",
         {{"default", {{"friction_angle", phi}, {"cohesion", cohesion}, {"tensile_strength", 0.0},
                       {"law", "coulomb_slip"}}}}},
        {"blocks", blocks},
        // Consolidated at double strength, so that blocks whose factor is below 1 stand.
        {"stages", {{{"duration", 0.3}, {"dynamic_coefficient", 0.0}, {"gravity_ramp", {0.0, 1.0}}}}},
    };
    return scene.dump();
  }
};

World consolidated_world(const std::string& text, double consolidation_factor = 0.5) {
  const Consolidation c = consolidate(parse_scene_text(text, "scene"), consolidation_factor,
                                      [](const World&, const RunStats&) { return true; });
  REQUIRE_FALSE(c.stats.diverged);
  return c.world;
}

}  // namespace

TEST_CASE("a block on a plane: the limit-analysis factor is the limit-equilibrium one",
          "[limit_analysis]") {
  OnPlane p;
  SECTION("friction alone: tan(phi) / tan(dip)") {
    const World w = consolidated_world(p.scene_text());
    const LimitAnalysisResult r = limit_analysis(w, LimitAnalysisSettings{});
    REQUIRE(r.computed);
    REQUIRE(r.found);
    const double le = std::tan(deg(35.0)) / std::tan(deg(30.0));  // 1.2128
    // The true factor lies in [factor, upper], which is kBracket wide.
    CHECK(r.factor <= le);
    CHECK(r.upper >= le);
    CHECK(r.upper - r.factor <= kBracket * r.factor);
    // Its mechanism: the block slides out of the slope. Associative friction makes the slip
    // dilate, the velocity leaving the plane at the reduced friction angle, which at the
    // factor equals the dip: from 30 degrees down the plane, 30 degrees up, so horizontal.
    // (A non-associative slide would run along the plane; the factor is the same.)
    REQUIRE(r.mechanism.size() == 1);
    CHECK(r.mechanism[0].velocity.x() == Approx(-1.0).margin(1e-3));
    CHECK(r.mechanism[0].velocity.y() == Approx(0.0).margin(1e-3));
    CHECK(std::abs(r.mechanism[0].angular_velocity) < 1e-3);
    // The block alone is its own single-block bound.
    const std::vector<BlockBound> bounds = single_block_bounds(w, LimitAnalysisSettings{});
    REQUIRE(bounds.size() == 1);
    CHECK(bounds[0].factor == Approx(r.factor).epsilon(1e-12));
    CHECK(bounds[0].upper == Approx(r.upper).epsilon(1e-12));
    // Capped by that bound (as dda fos runs it), the search tries just below the cap, finds
    // it admissible, and solves once more at the cap for the mechanism: two programs, the
    // same closed form in the bracket.
    LimitAnalysisSettings capped;
    capped.known_inadmissible = bounds[0].upper;
    const LimitAnalysisResult c = limit_analysis(w, capped);
    REQUIRE(c.found);
    CHECK(c.programs == 2);
    CHECK(c.factor <= le);
    CHECK(c.upper >= le);
  }
  SECTION("with cohesion: (W cos(dip) tan(phi) + c L) / (W sin(dip))") {
    p.cohesion = 20e3;
    const World w = consolidated_world(p.scene_text());
    const LimitAnalysisResult r = limit_analysis(w, LimitAnalysisSettings{});
    REQUIRE(r.found);
    const double weight = 2500.0 * 9.81 * 10.0 * 4.0;
    const double le = (weight * std::cos(deg(30.0)) * std::tan(deg(35.0)) + 20e3 * 10.0) /
                      (weight * std::sin(deg(30.0)));  // 1.4167
    CHECK(r.factor <= le);
    CHECK(r.upper >= le);
  }
  SECTION("Barton-Bandis: the friction at each contact's consolidated normal stress") {
    // phi_r 25, JRC 10, JCS 50 MPa: the block's two base contacts (5 m of base each) carry
    // unequal shares of W cos 30 (its moment), so the factor lies between the law's at the
    // two stresses, tan(phi(sigma)) / tan 30 (about 2.3: 52 degrees at 85 kPa).
    p.phi = 25.0;
    json scene = json::parse(p.scene_text());
    scene["joint_materials"]["default"]["jrc"] = 10.0;
    scene["joint_materials"]["default"]["jcs"] = 5e7;
    const World w = consolidated_world(scene.dump());
    double lo = 90.0, hi = 0.0;
    int carrying = 0;
    for (const Contact& c : w.contacts) {
      if (c.state.normal_force <= 0.0) continue;
      const double angle = barton_bandis_angle(25.0, 10.0, 5e7, c.state.normal_force / c.length);
      lo = std::min(lo, angle);
      hi = std::max(hi, angle);
      ++carrying;
    }
    REQUIRE(carrying == 2);
    const LimitAnalysisResult r = limit_analysis(w, LimitAnalysisSettings{});
    REQUIRE(r.found);
    INFO("factor " << r.factor << ", the law's between " << lo << " and " << hi << " degrees");
    CHECK(r.upper >= std::tan(deg(lo)) / std::tan(deg(30.0)));
    CHECK(r.factor <= std::tan(deg(hi)) / std::tan(deg(30.0)));
    CHECK(lo > 45.0);  // far above phi_r's tan 25 / tan 30 = 0.81
  }
}

TEST_CASE("a block that can only topple has no factor above zero, and a squat one slides",
          "[limit_analysis]") {
  // On a plane of 30 degrees a block whose width along the plane is below tan(30) x its
  // height tips over its lower edge whatever the friction (its weight's line falls outside
  // its base): not admissible even at the smallest factor. Friction 60 degrees keeps it
  // from sliding first.
  OnPlane tall;
  tall.phi = 60.0;
  tall.widths = {2.0};
  tall.height = 4.0;  // 2 / 4 = 0.5 < tan 30 = 0.577
  const World w = consolidated_world(tall.scene_text(), 0.01);
  const LimitAnalysisResult r = limit_analysis(w, LimitAnalysisSettings{});
  REQUIRE(r.computed);
  CHECK_FALSE(r.found);
  CHECK_FALSE(r.admissible_at_max);
  // 2.6 / 4 = 0.65 > tan 30: it stands on its base, and slides at tan 60 / tan 30 = 3.
  OnPlane squat = tall;
  squat.widths = {2.6};
  const LimitAnalysisResult s = limit_analysis(consolidated_world(squat.scene_text(), 0.5),
                                               LimitAnalysisSettings{});
  REQUIRE(s.found);
  CHECK(s.factor <= 3.0);
  CHECK(s.upper >= 3.0);
}

TEST_CASE("two blocks side by side on a plane share their friction: the pair's factor",
          "[limit_analysis]") {
  // Both on the same plane with the same friction: each alone and the pair together fail at
  // tan(phi) / tan(dip), and the upper block pushing the lower changes nothing.
  OnPlane p;
  p.widths = {4.0, 6.0};
  p.height = 3.0;
  const World w = consolidated_world(p.scene_text());
  const LimitAnalysisResult r = limit_analysis(w, LimitAnalysisSettings{});
  REQUIRE(r.found);
  const double le = std::tan(deg(35.0)) / std::tan(deg(30.0));
  CHECK(r.factor <= le);
  CHECK(r.upper >= le);
}

TEST_CASE("the slope verification's rigid mechanisms: limit analysis against limit equilibrium",
          "[limit_analysis]") {
  // Planar sliding (with and without cohesion, with uplift) is a pure slide on one plane,
  // where associative and non-associative friction give the same factor: the limit
  // analysis must bracket the closed form. (The wedges and the toppling columns dilate in
  // the associative mechanism; their factors are compared in verification/slope.)
  for (const slope::SlopeCase& c : slope::all_cases(0.002)) {
    if (c.name.rfind("planar", 0) != 0 || c.seismic_coefficient != 0.0) continue;
    INFO(c.name);
    World w = consolidated_world(c.scene, c.le_factor < 1.05 ? 0.5 : 1.0);
    const LimitAnalysisResult r = limit_analysis(w, LimitAnalysisSettings{});
    REQUIRE(r.found);
    CHECK(r.factor <= c.le_factor * (1.0 + 1e-6));
    CHECK(r.upper >= c.le_factor * (1.0 - 1e-6));
  }
}

TEST_CASE("a failing trial's mechanism: the block slides down its plane, and its group's bound "
          "is its limit-analysis factor",
          "[limit_analysis]") {
  OnPlane p;
  const World w = consolidated_world(p.scene_text());
  const FosSettings s = resolve_fos_settings(w, FosSettings{});
  // tan 35 / tan 30 = 1.213: at F = 1.5 the block accelerates at g (sin 30 - cos 30 tan 35 /
  // 1.5) = 0.096 g, far above the verdict's 0.002 g.
  const TrialResult t = run_trial(w, s, 1.5);
  REQUIRE_FALSE(t.stable);
  const TrialMechanism m = trial_mechanism(w, t.world, LimitAnalysisSettings{});
  REQUIRE(m.blocks.size() == 1);
  CHECK(m.mode == "sliding");
  CHECK(m.blocks[0].mode == "sliding");
  // A slide along the plane: the displacement's direction is the plane's, down the dip, to
  // the round-off of its contact springs (1e-4 of the slip).
  const Vec2 down(-std::cos(deg(30.0)), -std::sin(deg(30.0)));
  const Vec2 u = m.blocks[0].displacement;
  CHECK(u.dot(down) == Approx(u.norm()).epsilon(1e-4));
  CHECK(std::abs(m.blocks[0].rotation) * 4.0 < 1e-3 * u.norm());
  // It slides on its one joint (the scene's "default", index 0) and lifts off nothing: the
  // contacts under its base (two corners) slide, none opens.
  REQUIRE(m.joints.size() == 1);
  CHECK(m.joints[0].joint == 0);
  CHECK(m.joints[0].sliding >= 2);
  CHECK(m.joints[0].opened == 0);
  REQUIRE(m.group_bound.found);
  const double le = std::tan(deg(35.0)) / std::tan(deg(30.0));
  CHECK(m.group_bound.factor <= le);
  CHECK(m.group_bound.upper >= le);
}

TEST_CASE("dda fos --method limit-analysis reports the second factor alone", "[limit_analysis][cli]") {
  const test::TempDir dir("dda_la_cli_");
  OnPlane p;
  test::write_file(dir.path / "plane.json", p.scene_text());
  const test::CommandResult run = test::run_command(
      std::string(DDA_EXE) + " fos " + test::shell_quote((dir.path / "plane.json").string()) +
      " --out " + test::shell_quote((dir.path / "out").string()) +
      " --method limit-analysis --consolidation-factor 0.5");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const json report = json::parse(test::read_file(dir.path / "out" / "report.json"));
  CHECK(report["method"] == "limit-analysis");
  CHECK(report["trials"].empty());
  const json& la = report["limit_analysis"];
  CHECK(la["computed"] == true);
  const double le = std::tan(deg(35.0)) / std::tan(deg(30.0));
  CHECK(la["bracket"][0].get<double>() <= le);
  CHECK(la["bracket"][1].get<double>() >= le);
  CHECK(la["single_block_bounds"].size() == 1);
  CHECK(la["mechanism"].size() == 1);
  CHECK(std::filesystem::file_size(dir.path / "out" / "limit_analysis.png") > 0);
}
