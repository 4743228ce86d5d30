#include "slope_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <utility>

#include "io/scene_reader.hpp"
#include "solver/run.hpp"
#include "studies/limit_analysis.hpp"
#include "studies/speculative_search.hpp"
#include "studies/strength_reduction.hpp"
#include "solver/world.hpp"
#include "contact/contact.hpp"

namespace dda::slope {
namespace {

constexpr double kLowFactorConsolidation = 0.5;

std::string trial_line(const std::string& name, const TrialResult& t) {
  std::ostringstream s;
  s.precision(4);
  s << "  " << name << ": F = " << t.factor << " " << (t.stable ? "stable" : "FAILS") << " ("
    << t.verdict << ", moved " << t.largest_displacement << " m, " << t.steps << " steps, "
    << t.wall_time_s << " s)";
  return s.str();
}

// A column's motion (README "Toppling modes"): vertex 0 is its toe-side base corner (the pivot
// of a topple), vertex 3 the toe-side top corner. A column whose corners moved less than a
// tenth of the most any column moved is stable; else it slides when its base corner moved at
// least half as far as its top (a rigid translation moves both alike), and topples otherwise.
std::vector<ColumnMotion> column_motions(const SlopeCase& c, const World& before, const World& after) {
  std::vector<ColumnMotion> out;
  double largest = 0.0;
  for (std::size_t k = 0; k < c.columns.size(); ++k) {
    const auto i = static_cast<std::size_t>(c.columns[k]);
    const Block& b0 = before.blocks[i];
    const Block& b1 = after.blocks[i];
    ColumnMotion m;
    m.column = static_cast<int>(k) + 1;
    m.rotation_deg = (b1.rotation - b0.rotation) * 180.0 / 3.14159265358979323846;
    m.base_slip = (b1.vertices[0] - b0.vertices[0]).norm();
    m.top_move = (b1.vertices[3] - b0.vertices[3]).norm();
    m.le_mode = k < c.le_modes.size() ? c.le_modes[k] : "";
    largest = std::max({largest, m.base_slip, m.top_move});
    out.push_back(m);
  }
  for (ColumnMotion& m : out) {
    if (std::max(m.base_slip, m.top_move) < 0.1 * largest) {
      m.mode = "stable";
    } else {
      m.mode = m.base_slip >= 0.5 * m.top_move ? "slide" : "topple";
    }
  }
  return out;
}

// The share of the limiting friction on each interface between neighbouring columns, from
// the contacts of `w` (a trial at factor F on joints of friction kToppleFriction / F).
std::vector<double> interface_shares(const SlopeCase& c, const World& w, double factor) {
  const double tan_phi = std::tan(kToppleFriction * 3.14159265358979323846 / 180.0) / factor;
  std::vector<double> out;
  for (std::size_t k = 0; k + 1 < c.columns.size(); ++k) {
    const int lower = c.columns[k], upper = c.columns[k + 1];
    double normal = 0.0, shear = 0.0;
    for (const Contact& ct : w.contacts) {
      const int a = ct.key.vertex_block, b = ct.key.edge_block;
      if (ct.state.mode == ContactMode::Open) continue;
      if (!((a == lower && b == upper) || (a == upper && b == lower))) continue;
      normal += ct.state.normal_force;
      shear += std::abs(ct.iterate.shear_force);
    }
    out.push_back(normal > 0.0 ? std::min(1.0, shear / (tan_phi * normal)) : 1.0);
  }
  return out;
}

}  // namespace

CaseResult run_case(const SlopeCase& c, const RunOptions& options,
                    const std::function<void(const std::string&)>& progress) {
  CaseResult r;
  r.name = c.name;
  r.allowed = 0.5 * options.tolerance + c.resolution;
  const auto start = std::chrono::steady_clock::now();
  Scene scene;
  try {
    scene = with_seismic_coefficient(parse_scene_text(c.scene, c.name), c.seismic_coefficient);
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (c.needs_water && what.find("water") != std::string::npos) {
      r.skipped = true;
      r.note = "water pressure not available in this build (the scene reader rejects the "
               "\"water\" key: " + what + ")";
      return r;
    }
    throw;
  }
  // Every time step, the stages' too (a trial runs on the last stage's), and the penalty.
  scene = with_spread_setting(std::move(scene), SpreadSetting{"", options.time_step_scale, options.penalty_scale});
  // A case whose factor is below 1 (the uplift and full-crack cases) cannot come to rest at
  // full strength: it consolidates at double strength (consolidation factor 0.5), else a
  // block that slid during the consolidation would have opened its tension crack before the
  // first trial. The others consolidate at full strength: where the forces between blocks
  // are statically indeterminate (the rough wedge's interface) the consolidation's strength
  // decides how they are shared. The trials reduce the scene's own strengths either way.
  const double consolidation_factor = c.le_factor < 1.0 ? kLowFactorConsolidation : 1.0;
  Consolidation consolidated = consolidate(scene, consolidation_factor,
                                           [](const World&, const RunStats&) { return true; });
  World& world = consolidated.world;
  const RunStats& consolidation = consolidated.stats;
  if (consolidation.diverged) {
    r.note = "the consolidation diverged: " + consolidation.message;
    return r;
  }
  FosSettings settings;
  settings.jobs = options.jobs;
  settings.tolerance = options.tolerance;
  settings.dynamic_coefficient = options.dynamic_coefficient;
  settings.seismic_coefficient = c.seismic_coefficient;
  settings = resolve_fos_settings(world, settings, consolidated.settling.relaxation_steps);
  r.failure_displacement = settings.failure_displacement;
  r.trial_time = settings.trial_time;
  // The second factor: rigid-block limit analysis of the same consolidated blocks.
  const LimitAnalysisResult limit = limit_analysis(world, LimitAnalysisSettings{});
  r.la_found = limit.found;
  r.la_factor = limit.factor;
  r.la_upper = limit.upper;
  r.la_note = limit.computed ? "" : limit.reason;
  FosResult fos = search_on_threads(
      settings,
      [&](double f, const StopQuery& stop) { return run_trial(world, settings, f, stop); },
      [&](const TrialResult& t) {
        if (progress) progress(trial_line(c.name, t));
      });
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.trials = static_cast<int>(fos.trials.size());
  r.found = fos.found;
  r.note = fos.message;
  for (const Block& b : world.blocks) {
    r.before.push_back(b.vertices);
    r.fixed.push_back(b.fixed);
  }
  if (!fos.found) return r;
  r.factor = fos.factor_of_safety;
  r.last_stable = fos.last_stable;
  r.first_failing = fos.first_failing;
  r.error = r.factor - c.le_factor;
  r.pass = std::abs(r.error) <= r.allowed;
  for (const TrialResult& t : fos.trials) {
    if (t.factor != fos.first_failing || t.stable) continue;
    for (const Block& b : t.world.blocks) r.after.push_back(b.vertices);
    if (!c.columns.empty()) {
      r.columns = column_motions(c, world, t.world);
      r.interface_shares = interface_shares(c, t.world, t.factor);
      r.le_mobilised = topple_factor(goodman_bray_slope(), kToppleFriction, r.interface_shares);
      r.error_mobilised = r.factor - r.le_mobilised;
      r.pass = std::abs(r.error_mobilised) <= r.allowed;
    }
    break;
  }
  if (!c.columns.empty()) {
    std::vector<double> factors;
    for (double f = 1.0; f < fos.first_failing - 1e-9; f += 0.05) factors.push_back(f);
    for (const TrialResult& t : run_trials(world, settings, factors, {})) {
      r.scan.push_back({t.factor, t.stable, t.largest_displacement});
    }
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return r;
}

}  // namespace dda::slope
