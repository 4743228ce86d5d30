// The paper reproduction's key numbers (in part): the full run of
// `dda_verify_paper` (about 2 s), its CSVs read back and held to closed forms and to the
// physics of each case. Each tolerance says why it is what it is.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"

namespace fs = std::filesystem;

namespace {

// A CSV as rows of named cells.
using Row = std::map<std::string, std::string>;

std::vector<Row> read_csv(const fs::path& path) {
  const std::vector<std::string> lines = dda::test::read_lines(path);
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
    return cells;
  };
  std::vector<Row> rows;
  if (lines.empty()) return rows;
  const std::vector<std::string> header = split(lines[0]);
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const std::vector<std::string> cells = split(lines[k]);
    Row row;
    for (std::size_t c = 0; c < header.size() && c < cells.size(); ++c) row[header[c]] = cells[c];
    rows.push_back(row);
  }
  return rows;
}

double number(const Row& row, const std::string& key) { return std::stod(row.at(key)); }

// The full reproduction, run once for all the cases below. ctest runs each case in a process
// of its own, so it runs the reproduction once beforehand (the fixture test paper_full_run,
// CMakeLists.txt) into DDA_PAPER_FULL_DIR, and a case uses that run when its report is newer
// than the program; otherwise (dda_tests run by hand, or a stale directory) the case runs
// it itself, into a directory removed when the process ends.
const fs::path& full_run() {
  static const dda::test::TempDir dir("dda-paper-full-");
  static const fs::path path = [] {
    const fs::path shared = DDA_PAPER_FULL_DIR;
    std::error_code ec;
    const fs::path report = shared / "report.md";
    if (fs::exists(report, ec) &&
        fs::last_write_time(report, ec) >= fs::last_write_time(DDA_PAPER_EXE, ec) && !ec) {
      return shared;
    }
    const auto r = dda::test::run_command(dda::test::shell_quote(DDA_PAPER_EXE) + " --out " +
                                          dda::test::shell_quote(dir.path.string()));
    if (r.exit_code != 0) throw std::runtime_error("dda_verify_paper failed:\n" + r.output);
    return dir.path;
  }();
  return path;
}

// Only the sliding block's and the plastic specimen's sweeps (--closed-form-only: about
// 0.5 s, against the full run's 2 to 3 s; the same numbers as the full run's CSVs).
const fs::path& closed_form_run() {
  static const dda::test::TempDir dir("dda-paper-closed-form-");
  static const bool ran = [] {
    const auto r = dda::test::run_command(dda::test::shell_quote(DDA_PAPER_EXE) +
                                          " --closed-form-only --out " +
                                          dda::test::shell_quote(dir.path.string()));
    if (r.exit_code != 0) throw std::runtime_error("dda_verify_paper failed:\n" + r.output);
    return true;
  }();
  (void)ran;
  return dir.path;
}

bool rotation_exact(const std::string& treatment) {
  return treatment == "post_adjustment" || treatment == "local_frame" ||
         treatment == "local_frame_as_printed" || treatment == "finite_rotation";
}

}  // namespace

TEST_CASE("paper reproduction: a freely spinning block's area follows each treatment's closed "
          "form",
          "[paper]") {
  // No force acts, so every step turns the block by r0 = omega dt exactly (omega = 1 rad/s)
  // and the treatments differ only in how they place the vertices: Shi's first-order T
  // stretches the block by 1 + r0^2 per step, the second-order update by 1 + r0^4/4, and the
  // exact rotations not at all (docs/scene-format.md, rotation treatments). After N steps
  // the area error is that factor to the N, less 1. Round-off: each step's area carries
  // ~1e-16 relative, so over at most 1257 steps the area ratio agrees to 1e-12 (measured:
  // 4e-14 at worst), and the exact treatments stay below 1e-13 (measured: 1.9e-15).
  int checked = 0;
  for (const Row& row : read_csv(full_run() / "speed_spin.csv")) {
    const std::string t = row.at("treatment");
    const double dt = number(row, "dt"), error = number(row, "area_rel_error");
    const int n = std::stoi(row.at("steps"));
    INFO(t << " dt " << dt << " steps " << n << " area error " << error);
    if (t == "original" || t == "second_order") {
      const double per_step = t == "original" ? 1.0 + dt * dt : 1.0 + std::pow(dt, 4) / 4.0;
      const double expected = std::pow(per_step, n) - 1.0;
      CHECK(std::abs(error - expected) <= 1e-12 * (1.0 + expected));
      ++checked;
    } else if (rotation_exact(t)) {
      CHECK(std::abs(error) < 1e-13);
      ++checked;
    }
  }
  CHECK(checked == 30);  // six treatments x five time steps
}

TEST_CASE("paper reproduction: the rigid pendulum's period converges at second order with "
          "finite_rotation",
          "[paper]") {
  // Against CVODE's rigid pendulum (1e-10 tolerances). The step's phase error is of second
  // order in dt for a treatment that rotates exactly within the step (finite_rotation): the
  // period error falls by 4 per halving. Measured orders 1.97 and 1.94 between dt = 0.04,
  // 0.02 and 0.01 s; [1.8, 2.2] would catch a first-order error (order 1, as Shi's T gives:
  // 0.50, 0.25, 0.11) or a lost one. Below dt = 0.01 s the error flattens (1.2e-5, 4.8e-6),
  // so the order is taken where the time step dominates.
  std::map<std::string, std::map<double, double>> period_error;
  for (const Row& row : read_csv(full_run() / "speed_pendulum.csv")) {
    period_error[row.at("treatment")][number(row, "dt")] = number(row, "period_rel_error");
  }
  const auto& fr = period_error.at("finite_rotation");
  for (const auto& [coarse, fine] : {std::pair{0.04, 0.02}, std::pair{0.02, 0.01}}) {
    const double order = std::log2(fr.at(coarse) / fr.at(fine));
    INFO("dt " << coarse << " -> " << fine << ": order " << order);
    CHECK(order >= 1.8);
    CHECK(order <= 2.2);
  }
  // At dt = 0.01 s: 3.9e-5 measured; 1e-4 is what second order from 5.9e-4 at 0.04 s allows
  // (5.9e-4 / 16 = 3.7e-5) with a factor 2.7 for the higher-order terms.
  CHECK(fr.at(0.01) < 1e-4);
  // Shi's first-order T: every halving of dt roughly halves the error (orders 0.85 to 1.19
  // measured over the sweep); at dt = 0.01 s it is still above 10 % (0.108).
  const auto& original = period_error.at("original");
  CHECK(original.at(0.01) > 0.1);
  const double original_order = std::log2(original.at(0.04) / original.at(0.01)) / 2.0;
  INFO("original: mean order " << original_order);
  CHECK(original_order > 0.8);
  CHECK(original_order < 1.3);
}

TEST_CASE("paper reproduction: only finite_rotation keeps the swinging octagon's energy",
          "[paper]") {
  // The paper's octagon pinned at a vertex and released from rest: a conservative pendulum
  // never swings past its mirror position (pi from the start) and never holds more
  // mechanical energy than it started with. The finding of this reproduction (its report,
  // "Energy and swing", and docs/scene-format.md on finite_rotation): the paper's own
  // local_frame, Ke's post_adjustment and the others gain energy and swing over the top;
  // finite_rotation does not.
  std::map<std::string, Row> by_treatment;
  for (const Row& row : read_csv(full_run() / "swinging_summary.csv")) {
    by_treatment[row.at("treatment")] = row;
  }
  const Row& fr = by_treatment.at("finite_rotation");
  CHECK(fr.at("status") == "completed");
  CHECK(fr.at("gains_energy") == "0");
  CHECK(number(fr, "max_swing") <= M_PI);
  // The swing reaches its mirror position to 3e-5 rad (measured 3.14156): the scheme's
  // damping of a pinned swing over 5000 steps is that small.
  CHECK(number(fr, "max_swing") > M_PI - 1e-4);
  for (const char* t : {"original", "second_order", "post_adjustment", "local_frame"}) {
    INFO(t);
    CHECK(by_treatment.at(t).at("gains_energy") == "1");
    CHECK(number(by_treatment.at(t), "max_swing") > M_PI);
  }
  // finite_rotation's drift over the 5000 steps: what the scheme's damping takes from the
  // pin's and the strain's fast modes (both at Omega > 4, where Shi's scheme damps little),
  // measured -3.2e-4 of m g l at the end, kinetic + potential less the pin's stored energy
  // at every step at most 0 (the flag above). Bound: a loss, and less than 1e-3 of m g l.
  double drift = 0.0;
  for (const Row& row : read_csv(full_run() / "swinging_energy.csv")) {
    if (row.at("treatment") == "finite_rotation") drift = number(row, "total");
  }
  INFO("finite_rotation: E - E0 at the end " << drift << " J");
  CHECK(drift <= 0.0);
  CHECK(drift > -1e-3 * number(fr, "mgl_J"));
}

TEST_CASE("paper reproduction: the falling octagon keeps its area within its elastic strain "
          "under every exact rotation",
          "[paper]") {
  // Table 1. A rotation-exact treatment changes the rock's area only by elastic strain. At
  // rest on the run-out under its own weight that is about rho g h / E = 28 kN/m^3 x 1 m /
  // 2 GPa = 1.4e-5 (measured 3e-8 to 4.4e-6 with Shi's open-close loop). But the octagon is
  // not always at rest when the run ends: with the converged contact solver (the default)
  // it is still rolling at step 300 under some settings (a vertex moves 0.6 m in the last 20
  // steps of finite_rotation's alternating run), and the strain of its impacts with the
  // run-out, bounded by v / c = 3 m/s / 845 m/s = 3.5e-3, is in the area: measured up to
  // 8.8e-5 (finite_rotation, alternating), 2.0e-5 (post_adjustment). 2e-4 bounds the
  // measured with room, and is a thousandth of what Shi's first-order T does: it inflates
  // the area by tens of per cent (measured 31 % to 108 %), the paper's point.
  int checked = 0;
  for (const Row& row : read_csv(full_run() / "falling_summary.csv")) {
    const std::string t = row.at("treatment");
    INFO(t << " " << row.at("setting"));
    CHECK(row.at("status") == "completed");
    if (rotation_exact(t)) {
      CHECK(number(row, "area_rel_error") < 2e-4);
      ++checked;
    } else if (t == "original") {
      CHECK(number(row, "area_rel_error") > 0.2);
      ++checked;
    }
  }
  CHECK(checked == 15);  // five treatments x three settings
}

TEST_CASE("paper reproduction: Table 1's original and second_order areas follow their closed "
          "forms over the rock's own rotations",
          "[paper]") {
  // Shi's first-order T multiplies a block's area by exactly 1 + r^2 in a step that turns it
  // by r, the second-order update by 1 + r^4 / 4 (docs/scene-format.md); the rock's strain
  // changes it besides by its volumetric strain: rho g h / E = 1.4e-5 at rest, more while it
  // strikes the run-out (measured at the end: 1e-6 to 3e-5, and 9e-5 for the alternating
  // setting of original, whose inflated rock ends in an impact). So the final area over the
  // product of the per-step factors of the rock's recorded rotations must be 1 within 2e-4,
  // three orders below the inflation it checks (0.3 to 1.08): a check of the inflation
  // that does not take it from the run's own area.
  std::map<std::string, std::vector<Row>> runs;
  for (const Row& row : read_csv(full_run() / "falling_area.csv")) {
    if (row.at("treatment") == "original" || row.at("treatment") == "second_order") {
      runs[row.at("treatment") + " " + row.at("setting")].push_back(row);
    }
  }
  CHECK(runs.size() == 6);
  for (const auto& [name, rows] : runs) {
    const bool original = name.rfind("original", 0) == 0;
    double product = 1.0;
    for (std::size_t k = 1; k < rows.size(); ++k) {
      const double r = number(rows[k], "rotation") - number(rows[k - 1], "rotation");
      product *= original ? 1.0 + r * r : 1.0 + std::pow(r, 4) / 4.0;
    }
    const double ratio = number(rows.back(), "area") / number(rows.front(), "area");
    INFO(name << ": area ratio " << ratio << ", closed form " << product);
    CHECK(std::abs(ratio / product - 1.0) < 2e-4);
    if (original) CHECK(product > 1.2);  // the inflation itself, 31 % to 108 %
  }
}

TEST_CASE("paper reproduction: a spinning block's stress is rho omega^2 J / A with the "
          "pseudo-rigid inertia and zero with Shi's",
          "[paper][inertia]") {
  // rotation_spin.csv: a 2 m x 1 m block of the paper's rock at 2 rad/s. The closed form
  // holds to first order in the strain, sigma / E = 2e-6 here (measured 4.2e-7 for
  // local_frame and finite_rotation, 2.2e-6 for local_frame_as_printed, whose placement is
  // off by the strain itself); bound 5e-6. Every treatment with Shi's inertia carries no
  // stress at all: error 1 to round-off.
  int pseudo_rigid = 0, shi = 0;
  for (const Row& row : read_csv(full_run() / "rotation_spin.csv")) {
    INFO(row.at("treatment") << " " << row.at("inertia") << " error " << row.at("rel_error"));
    CHECK(row.at("status") == "completed");
    if (row.at("inertia") == "pseudo_rigid") {
      CHECK(number(row, "rel_error") < 5e-6);
      ++pseudo_rigid;
    } else {
      CHECK(std::abs(number(row, "rel_error") - 1.0) < 1e-9);
      ++shi;
    }
  }
  // local_frame, local_frame_as_printed, finite_rotation, finite_rotation_polar
  CHECK(pseudo_rigid == 4);
  // four treatments without a block frame, `paper` (Shi's inertia as printed), and
  // local_frame and finite_rotation once more with Shi's
  CHECK(shi == 7);
}

TEST_CASE("paper reproduction: the swinging octagon's stress follows the quasi-static closed "
          "form with finite_rotation",
          "[paper][inertia]") {
  // rotation_swing_summary.csv, over one period at dt 0.02 s. The closed form (CVODE's
  // rigid pendulum, pin force, centrifugal and Euler loads) is exact for a slow swing to
  // first order in (swing rate / strain mode)^2 = (1.7 / 350)^2; what separates DDA from it
  // is the step: its frame lags by a fraction of a step's turn (measured: finite_rotation
  // rms 1.04e-2, and at most 1.33e-2 of the largest stress after the release's first 0.1 s,
  // when the unstressed block meets the closed form's sudden load). Bounds at twice those.
  // Shi's inertia misses the centrifugal load: at least 15 % somewhere (measured 18-19 %),
  // and the other first-order treatments do no better.
  std::map<std::string, Row> by_run;
  for (const Row& row : read_csv(full_run() / "rotation_swing_summary.csv")) {
    by_run[row.at("treatment") + " " + row.at("inertia")] = row;
  }
  const Row& fr = by_run.at("finite_rotation pseudo_rigid");
  CHECK(number(fr, "rms_rel_error") < 2e-2);
  CHECK(number(fr, "max_rel_error") < 3e-2);
  // The largest stress, 336 kPa, is the closed form's: m g at the pin over the block's
  // area and more (a check that the reference itself did not change).
  CHECK(number(fr, "largest_Pa") == Approx(336e3).epsilon(0.01));
  for (const char* key : {"finite_rotation shi", "local_frame shi", "post_adjustment shi"}) {
    INFO(key);
    CHECK(number(by_run.at(key), "max_rel_error") > 0.15);
  }
}

TEST_CASE("paper reproduction: the swinging octagon's energy gain is first order in dt, "
          "independent of the pin, and absent with finite_rotation",
          "[paper]") {
  // rotation_gain.csv over 20 s, the gain of the block's own energy (kinetic, potential,
  // strain). local_frame, post_adjustment and the paper's method as printed (`paper`) at dt
  // 0.04, 0.02, 0.01, 0.005 s: 1.28, 0.563, 0.235, 0.109 of m g l (measured orders 1.19,
  // 1.26, 1.10); each halving must cut the gain by 2^0.8 at least and by 2^1.5 at most
  // (first order, not second, not a constant). At dt 0.02 s the pin stiffness 5 E, 50 E,
  // 500 E changes the gain by 2.5e-4 of itself (bound 1e-2: a gain caused by the pin's
  // compliance would scale with 1/stiffness, a factor 100 here). finite_rotation and the
  // default finite_rotation_polar gain nothing but the strain energy of the swing's elastic
  // oscillation: 4.4e-5 m g l at dt 0.04 s, 8.9e-6 with the 500 E pin, 0 otherwise (bound
  // 1e-4).
  std::map<std::string, std::map<double, double>> by_dt;
  std::map<std::string, std::vector<double>> by_penalty;
  for (const Row& row : read_csv(full_run() / "rotation_gain.csv")) {
    if (row.at("study") == "dt") by_dt[row.at("treatment")][number(row, "dt")] = number(row, "gain_over_mgl");
    if (row.at("study") == "penalty" || number(row, "dt") == 0.02) {
      by_penalty[row.at("treatment")].push_back(number(row, "gain_over_mgl"));
    }
  }
  for (const char* t : {"local_frame", "post_adjustment", "paper"}) {
    const auto& g = by_dt.at(t);
    CHECK(g.at(0.02) > 0.4);
    for (const auto& [coarse, fine] : {std::pair{0.04, 0.02}, std::pair{0.02, 0.01}, std::pair{0.01, 0.005}}) {
      const double order = std::log2(g.at(coarse) / g.at(fine));
      INFO(t << " dt " << coarse << " -> " << fine << ": order " << order);
      CHECK(order > 0.8);
      CHECK(order < 1.5);
    }
    const auto& p = by_penalty.at(t);
    REQUIRE(p.size() == 3);
    const auto [lo, hi] = std::minmax_element(p.begin(), p.end());
    CHECK(*hi / *lo - 1.0 < 1e-2);
  }
  for (const char* t : {"finite_rotation", "finite_rotation_polar"}) {
    for (const auto& [dt, gain] : by_dt.at(t)) {
      INFO(t << " dt " << dt);
      CHECK(gain <= 1e-4);
    }
    for (const double gain : by_penalty.at(t)) CHECK(gain <= 1e-4);
  }
}

TEST_CASE("paper reproduction: the octagon's period and swing against CVODE's rigid pendulum",
          "[paper]") {
  // rotation_pendulum.csv, dt 0.02 s. For a step exact in rotation the phase error is
  // second order, (omega0 dt)^2 / 12 ~ 5e-5 of the period here, more at large amplitude
  // (measured 1.1e-4; bound 3e-4), and the swing reaches pi to the step's resolution
  // (measured 5e-6 rad; bound 1e-4). The first-order treatments are off by 0.3 % to 2.5 %
  // (bound: above 3e-3) and overshoot pi.
  for (const Row& row : read_csv(full_run() / "rotation_pendulum.csv")) {
    const std::string t = row.at("treatment");
    INFO(t << ": period error " << row.at("period_rel_error") << ", first swing "
           << row.at("first_swing"));
    if (t == "finite_rotation" || t == "finite_rotation_polar") {
      CHECK(std::abs(number(row, "period_rel_error")) < 3e-4);
      CHECK(std::abs(number(row, "first_swing") - M_PI) < 1e-4);
    } else {
      CHECK(std::abs(number(row, "period_rel_error")) > 3e-3);
      CHECK(number(row, "first_swing") > M_PI);
    }
  }
}

TEST_CASE("paper reproduction: a block sliding down an incline and a Mohr-Coulomb specimen "
          "against their closed forms over dt",
          "[paper]") {
  // The work-precision sweeps of speed_incline.csv and speed_plastic.csv.
  SECTION("the sliding block: d = g (sin a - cos a tan phi) t^2 / 2") {
    const std::vector<Row> rows = read_csv(closed_form_run() / "speed_incline.csv");
    REQUIRE(rows.size() == 8);
    const double g = 9.81, a = M_PI / 6.0, tan_phi = std::tan(20.0 * M_PI / 180.0);
    const double acc = g * (std::sin(a) - std::cos(a) * tan_phi);
    std::map<double, Row> by_dt;
    for (const Row& row : rows) {
      const double dt = number(row, "dt");
      by_dt[dt] = row;
      INFO("dt " << dt << ": error " << row.at("rel_error") << ", lag / dt "
                 << row.at("lag_over_dt") << ", acceleration error " << row.at("acc_rel_error")
                 << ", Omega " << row.at("omega_dt"));
      CHECK(row.at("status") == "completed");
      CHECK(row.at("cut_steps") == "0");  // every run took the dt it was given
      CHECK_THAT(number(row, "acc_ref"), Catch::Matchers::WithinRel(acc, 1e-12));
      // Once sliding, Shi's step is exact for a constant force: the acceleration from the
      // travel between 1 s and 2 s is the closed form's up to the positions' elastic
      // compliance, m g sin a / E = 1427 x 9.81 x 0.5 / 2e9 = 3.5e-6 m, which moves
      // (sqrt d2 - sqrt d1)^2 by at most 5.8e-6 relative (d1 = 0.91 m, d2 = 3.63 m):
      // 1e-5 (measured 2.5e-8 to 8.3e-7).
      CHECK(number(row, "acc_rel_error") <= 1e-5);
    }
    // Omega = dt sqrt(2 p / m) >> 1 (dt >= 5 ms, Omega >= 59). With Shi's open-close loop the
    // unloaded contact springs took the whole first step to load and it was lost (measured
    // tau = 0.949, 0.987, 0.997 dt at Omega 59, 118, 237). The converged contact solver (the
    // default, docs/contact-solver.md) finds the sliding state within the first step: the
    // block leaves at once, its lag only the start's elastic compliance m g sin a / E over
    // the acceleration's scale (measured -7.3e-6, -1.5e-5, -3.0e-5 dt): 1e-4 dt bounds it.
    for (const double dt : {0.02, 0.01, 0.005}) {
      const Row& row = by_dt.at(dt);
      INFO("dt " << dt << ": lag / dt " << row.at("lag_over_dt"));
      CHECK(number(row, "omega_dt") > 50.0);
      CHECK(std::abs(number(row, "lag_over_dt")) <= 1e-4);
      // So the error is no longer first order in dt (2 tau / t with Shi's loop, measured
      // order 1.007): it is the compliance's floor at every dt, 3.5e-6 m against the 0.906 m
      // travel, 3.9e-6 relative (measured 2.9e-7 to 3.0e-7).
      CHECK(number(row, "rel_error") <= 3.5e-6 / 0.906);
    }
    // At the finest dt (Omega ~ 1) the step resolves the springs' oscillation, which Shi's
    // scheme damps by about Omega / 4 a cycle, i.e. over 4 / (omega^2 dt) s; while it lasts
    // friction (tan phi times the oscillating normal force) can miss or add at most
    // g cos a tan phi over that time, so |tau| <= g cos a tan phi 4 / (omega^2 dt) / acc
    // (4.9e-4 s at dt = 1e-4 s; measured 2.5e-4 s, the block ahead). This is the penalty
    // model's own start, which a smaller dt does not remove: the error's floor (5.1e-4).
    const Row& finest = by_dt.at(1e-4);
    const double omega_sq =
        2.0 * number(finest, "penalty") / number(finest, "mass");
    const double bound = g * std::cos(a) * tan_phi * 4.0 / (omega_sq * 1e-4) / acc;
    INFO("finest: lag " << finest.at("lag") << " s, bound " << bound << " s, error "
                        << finest.at("rel_error"));
    CHECK(std::abs(number(finest, "lag")) <= bound);
    CHECK(number(finest, "rel_error") <= 2.0 * bound / 1.0 + 1e-6);
  }
  SECTION("the plastic specimen: s1 = N s3 + 2 c sqrt(N)") {
    const std::vector<Row> rows = read_csv(closed_form_run() / "speed_plastic.csv");
    REQUIRE(rows.size() == 5);
    const double s = std::sin(M_PI / 6.0), n = (1.0 + s) / (1.0 - s);
    const double strength = n * 1e6 + 2e6 * std::sqrt(n);
    std::map<double, Row> by_dt;
    for (const Row& row : rows) {
      const double dt = number(row, "dt");
      by_dt[dt] = row;
      const double h = number(row, "height");
      INFO("dt " << dt << ": error on the present height " << row.at("error_signed")
                 << ", lag term " << row.at("lag_term") << ", nominal " << row.at("error_nominal"));
      CHECK(row.at("status") == "completed");
      CHECK_THAT(number(row, "strength"), Catch::Matchers::WithinRel(strength, 1e-12));
      // The return is exact on the yield surface (round-off of 6.5e6 Pa: measured 1.4e-16).
      CHECK(number(row, "yield_residual") <= 1e-12);
      // The lag term is one step's shortening, N P (v dt) / h^2, v = 1e-3 m/s.
      CHECK_THAT(number(row, "lag_term"),
                 Catch::Matchers::WithinRel(n * 1e6 * 1e-3 * dt / (h * h) / strength, 1e-12));
      // Against the nominal s3 = P the shortening itself counts, N P (1 / h - 1) <=
      // N P 2e-3 / (1 - 2e-3) for the whole push: 9.3e-4 of the strength (measured 8.4e-4 to
      // 8.6e-4 at every dt); 1e-3.
      CHECK(number(row, "error_nominal") <= 1e-3);
    }
    // Two terms make the error on the present height: minus the lag term (first order) and
    // static analysis' 2 M / dt^2 resisting each step's movement with 2 M v / dt (the
    // remainder, of order 1 / dt). Remainder x dt is the same at every dt: measured 4.68e-9
    // to 4.77e-9 s from 0.02 s down, within 5 % of the finest's. (At 0.04 s, 5.05e-9: there
    // the remainder is 0.7 % of the lag term, so a shortening a step 5e-4 short of v dt, the
    // share the platen and the springs take as s1 creeps up, shows as 8 %; not checked.)
    const double c = number(by_dt.at(0.0025), "inertia_term") * 0.0025;
    for (const double dt : {0.02, 0.01, 0.005, 0.0025}) {
      INFO("dt " << dt << ": remainder x dt " << number(by_dt.at(dt), "inertia_term") * dt);
      CHECK_THAT(number(by_dt.at(dt), "inertia_term") * dt, Catch::Matchers::WithinRel(c, 0.05));
    }
    // Where the lag dominates the order is 1 (measured 1.03 from 0.04 to 0.02 s): with the
    // remainder c / dt of the other sign, e(dt) = A dt - c / dt, the order from 0.04 to 0.02
    // is 1.03 for these numbers; [0.95, 1.1] allows for it and catches a lost order.
    const double order = number(by_dt.at(0.02), "order");
    INFO("order from 0.04 to 0.02 s: " << order);
    CHECK(order >= 0.95);
    CHECK(order <= 1.1);
  }
}

TEST_CASE("paper reproduction: Tables 2-3's block stress against the closed form at steps 200, "
          "2000 and 5000",
          "[paper][inertia]") {
  // rotation_table3.csv: the stress at the steps of Tables 2-3 (t = 4, 40, 100 s) against
  // the quasi-static closed form on CVODE's pendulum at that time. finite_rotation with the
  // pseudo-rigid inertia stays on it over the 5000 steps (measured 1.2e-2, 1.4e-2, 7.2e-3 of
  // the largest stress; its period is 1.1e-4 from CVODE's, so after 16 swings its phase has
  // moved by 0.01 rad; bound 3e-2, the swing's own bound). The paper's local_frame and Ke's
  // post_adjustment have gained energy by step 2000 and their stress is off by more than
  // the largest stress itself (measured 1.07 to 57); Shi's inertia misses the centrifugal
  // load at step 200 (measured 10 to 14 %).
  std::map<std::string, std::map<int, double>> error;
  for (const Row& row : read_csv(full_run() / "rotation_table3.csv")) {
    error[row.at("treatment") + " " + row.at("inertia")][std::stoi(row.at("step"))] =
        number(row, "rel_error");
  }
  for (int step : {200, 2000, 5000}) {
    INFO("step " << step);
    CHECK(error.at("finite_rotation pseudo_rigid").at(step) < 3e-2);
  }
  CHECK(error.at("local_frame pseudo_rigid").at(2000) > 0.5);
  CHECK(error.at("post_adjustment shi").at(2000) > 0.5);
  CHECK(error.at("finite_rotation shi").at(200) > 0.05);
}
