#include "studies/settings_spread.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "solver/world.hpp"
#include "studies/speculative_search.hpp"

namespace dda {
namespace {

std::string percent(double share) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f %%", 100.0 * share);
  return buf;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", x);
  return buf;
}

}  // namespace

double trial_time_step(const Scene& scene) {
  const std::vector<double>& steps =
      scene.stages.empty() ? scene.control.time_steps : scene.stages.back().time_steps;
  return *std::min_element(steps.begin(), steps.end());
}

Scene with_spread_setting(Scene scene, const SpreadSetting& setting) {
  if (setting.time_step_scale != 1.0) {
    for (double& dt : scene.control.time_steps) dt *= setting.time_step_scale;
    // The reader gives every stage its own copy of control's time steps where it gives none,
    // and a trial runs on the last stage's: scaling control's alone changes nothing.
    for (StageSpec& stage : scene.stages) {
      for (double& dt : stage.time_steps) dt *= setting.time_step_scale;
    }
  }
  if (setting.penalty_scale != 1.0) {
    scene.control.penalty = setting.penalty_scale * resolve_penalty(scene);
  }
  return scene;
}

SpreadFactor factor_at_setting(const Scene& scene, const SpreadSetting& setting,
                               double consolidation_factor, const FosSettings& settings,
                               const std::function<void(const TrialResult&)>& on_trial,
                               const StopQuery& stop) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  SpreadFactor f;
  f.setting = setting.name;
  f.time_step_scale = setting.time_step_scale;
  f.penalty_scale = setting.penalty_scale;
  const Scene varied = with_spread_setting(scene, setting);
  f.penalty = resolve_penalty(varied);
  f.time_step = trial_time_step(varied);
  const Consolidation consolidated =
      consolidate(varied, consolidation_factor,
                  [&stop](const World&, const RunStats&) { return !(stop && stop()); });
  if (consolidated.stats.interrupted) {
    f.interrupted = true;
    f.message = "interrupted during the consolidation";
    f.wall_time_s = elapsed();
    return f;
  }
  if (consolidated.stats.diverged) {
    f.message = "the consolidation diverged: " + consolidated.stats.message;
    f.wall_time_s = elapsed();
    return f;
  }
  const World& world = consolidated.world;
  const FosSettings resolved = resolve_fos_settings(world, settings, consolidated.settling.relaxation_steps);
  const FosResult r = search_on_threads(
      resolved,
      [&](double factor, const StopQuery& q) { return run_trial(world, resolved, factor, q); },
      on_trial, stop);
  f.found = r.found;
  f.interrupted = r.interrupted;
  if (r.found) {
    f.factor = r.factor_of_safety;
    f.last_stable = r.last_stable;
    f.first_failing = r.first_failing;
  } else {
    f.message = r.message;
  }
  f.trials = static_cast<int>(r.trials.size());
  f.wall_time_s = elapsed();
  return f;
}

SettingsSpread judge_spread(double factor_of_safety, double bracket_width,
                            std::vector<SpreadFactor> factors) {
  SettingsSpread s;
  s.computed = true;
  s.factors = std::move(factors);
  std::vector<double> found{factor_of_safety};
  std::string missing;
  const SpreadFactor* lowest = nullptr;
  const SpreadFactor* highest = nullptr;
  double widest = bracket_width;
  for (const SpreadFactor& f : s.factors) {
    if (!f.found) {
      missing += (missing.empty() ? "" : ", ") + f.setting;
      continue;
    }
    found.push_back(f.factor);
    widest = std::max(widest, f.first_failing - f.last_stable);
    if (lowest == nullptr || f.factor < lowest->factor) lowest = &f;
    if (highest == nullptr || f.factor > highest->factor) highest = &f;
  }
  const auto [lo, hi] = std::minmax_element(found.begin(), found.end());
  double mean = 0.0;
  for (double f : found) mean += f / static_cast<double>(found.size());
  s.spread = found.size() > 1 && mean > 0.0 ? (*hi - *lo) / mean : 0.0;
  s.resolution = mean > 0.0 ? widest / mean : 0.0;
  s.within = missing.empty() && s.spread <= kSpreadAgreement;
  const std::string range = "F from " + number(*lo) + " to " + number(*hi);
  const std::string over = "over dt / 5 to x 5 and the penalty / 10 to x 10";
  if (!missing.empty()) {
    s.text = "no factor found at " + missing + "; the others lie within " + percent(s.spread) +
             " (" + range + ")";
  } else if (s.within) {
    s.text = "the factor holds within " + percent(s.spread) + " " + over + " (" + range + ")";
  } else {
    // The scene's own settings are named first where they share the end with a setting.
    const auto named = [&](const SpreadFactor* f, double x) {
      return x == factor_of_safety || f == nullptr ? std::string("the scene's settings") : f->setting;
    };
    s.text = "the factor moves by " + percent(s.spread) + " " + over + " (" + range +
             ", lowest at " + named(lowest, *lo) + ", highest at " + named(highest, *hi) +
             "), more than " + percent(kSpreadAgreement) +
             ": it depends on the time step or the contact stiffness as well as on the slope; "
             "plan with the lowest, F = " + number(*lo) + " (docs/factor-of-safety.md, section 6)";
  }
  if (found.size() > 1) {
    s.text += "; each factor is its search's bracket's midpoint, so the spread is known to " +
              percent(s.resolution) + " (a smaller --tolerance narrows the brackets)";
  }
  return s;
}

}  // namespace dda
