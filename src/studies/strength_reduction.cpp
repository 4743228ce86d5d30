#include "studies/strength_reduction.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <optional>
#include <thread>

#include "solver/run.hpp"
#include "solver/schedule.hpp"
#include "studies/recent_motion.hpp"
#include "studies/trial_watch.hpp"

namespace dda {
namespace {

double reduced_angle_deg(double angle_deg, double factor) {
  return std::atan(std::tan(angle_deg * M_PI / 180.0) / factor) * 180.0 / M_PI;
}

// Where the points a trial watches are: the monitors when the scene has any (the user's
// choice of what failing means), else the centroid of every free block. (Their speeds are
// taken from these positions over windows of steps, run_trial.)
std::vector<Vec2> watched_points(const World& w) {
  std::vector<Vec2> out;
  if (!w.monitors.empty()) {
    for (const Monitor& m : w.monitors) out.push_back(m.current);
    return out;
  }
  return free_block_centroids(w);
}

double total_kinetic(const World& w) {
  double k = 0.0;
  for (const Block& b : w.blocks) {
    if (!b.fixed) k += kinetic_energy(w, b);
  }
  return k;
}

struct Bracket {
  std::optional<double> stable;   // the largest stable F below `failing`
  std::optional<double> failing;  // the smallest failing F
  bool monotone = true;           // no stable trial above a failing one
};

// Over the judged trials (an interrupted one has no verdict).
Bracket bracket_of(const std::vector<TrialResult>& trials) {
  Bracket b;
  for (const TrialResult& t : trials) {
    if (!t.interrupted && !t.stable && (!b.failing || t.factor < *b.failing)) b.failing = t.factor;
  }
  for (const TrialResult& t : trials) {
    if (t.interrupted || !t.stable) continue;
    if (b.failing && t.factor >= *b.failing) {
      b.monotone = false;
      continue;
    }
    if (!b.stable || t.factor > *b.stable) b.stable = t.factor;
  }
  return b;
}

}  // namespace

JointLaw reduced_joint_law(const JointLaw& law, double factor) {
  assert(factor > 0.0);
  JointLaw r = law;
  // A Barton-Bandis joint keeps phi_r and divides the friction it computes (law_at_stress).
  if (law.jcs > 0.0) {
    r.friction_divisor = law.friction_divisor * factor;
  } else {
    r.tan_phi = law.tan_phi / factor;
  }
  r.cohesion = law.cohesion / factor;
  r.tensile_strength = law.tensile_strength / factor;
  r.residual_tan_phi = law.residual_tan_phi / factor;
  r.residual_cohesion = law.residual_cohesion / factor;
  return r;
}

MaterialParameters reduced_material(const MaterialParameters& m, double factor) {
  assert(factor > 0.0);
  MaterialParameters r = m;
  if (FrictionalStrength* p = frictional_strength(r)) {
    p->cohesion /= factor;
    for (HardeningPoint& h : p->hardening) h.cohesion /= factor;
    p->friction_angle = reduced_angle_deg(p->friction_angle, factor);
    p->dilation_angle = std::min(p->dilation_angle, p->friction_angle);
  }
  if (auto* mc = std::get_if<MohrCoulombParameters>(&r.model_parameters)) {
    if (mc->tensile_strength) *mc->tensile_strength /= factor;
  }
  return r;
}

Scene with_seismic_coefficient(Scene scene, double kh) {
  scene.gravity.x() += kh * scene.gravity.norm();
  return scene;
}

Consolidation consolidate(const Scene& scene, double factor, const StepObserver& observe) {
  assert(factor > 0.0);
  auto reduce = [factor](JointMaterial& j) {
    j.friction_angle = reduced_angle_deg(j.friction_angle, factor);
    j.cohesion /= factor;
    j.tensile_strength /= factor;
  };
  Scene stronger = scene;
  for (JointMaterial& j : stronger.joint_materials) reduce(j);
  for (StageSpec& stage : stronger.stages) {
    for (StageJoint& j : stage.joint_materials) reduce(j.material);
  }
  Consolidation out{make_world(stronger), {}, {}};
  out.stats = run(out.world, observe);
  // Settled with the consolidation's own (reduced) joint laws, before the scene's return.
  if (!out.stats.diverged && !out.stats.interrupted) {
    World before = out.world;
    out.settling = settle_to_rest(out.world, SettlingSettings{},
                                  [&] { return observe(out.world, out.stats); });
    // A slope that does not settle at the consolidation's strength (its factor is below it)
    // is not made to creep on: the trials start from where the scene's run left it. The steep
    // toppling slopes of verification/slope-cut (factor about 0.58) crept 800 static steps
    // with a quarter of a block's weight out of balance, lost blocks off their face, and then
    // failed every trial down to F = 0.1.
    if (out.settling.stopped == "not settling") {
      out.world = std::move(before);
      out.settling.kept = false;
    }
    // A settling stopped by the caller, or diverged, ends the consolidation so.
    if (out.settling.stats.diverged) {
      out.stats.diverged = true;
      out.stats.message = out.settling.stats.message;
    } else if (out.settling.stopped == "interrupted") {
      out.stats.interrupted = true;
    }
  }
  // The trials reduce the scene's own strengths (scene_joint_laws), not the consolidation's.
  std::vector<JointLaw> laws;
  for (const JointMaterial& j : scene.joint_materials) laws.push_back(joint_law_of(j));
  if (out.world.stages.stages.empty()) {
    out.world.joint_laws = laws;
  } else {
    out.world.stages.joint_laws = laws;
  }
  return out;
}

std::vector<JointLaw> scene_joint_laws(const World& consolidated) {
  return consolidated.stages.stages.empty() ? consolidated.joint_laws
                                            : consolidated.stages.joint_laws;
}

double median_free_block_area(const World& world) {
  std::vector<double> areas;
  for (const Block& b : world.blocks) {
    if (!b.fixed) areas.push_back(b.moments.area);
  }
  assert(!areas.empty());
  std::nth_element(areas.begin(), areas.begin() + static_cast<long>(areas.size() / 2), areas.end());
  return areas[areas.size() / 2];
}

FosSettings resolve_fos_settings(const World& consolidated, FosSettings s,
                                 double relaxation_steps) {
  if (s.failure_displacement <= 0.0) {
    s.failure_displacement = 0.05 * std::sqrt(median_free_block_area(consolidated));
    // Joint water acts on the contacts found within the search distance: a trial judged
    // beyond it would have lost the water in a joint that opened (a tension crack's thrust).
    if (consolidated.water) {
      s.failure_displacement = std::min(s.failure_displacement, consolidated.search_distance);
    }
  }
  if (s.trial_time <= 0.0) {
    const double g = std::max(consolidated.gravity.norm(), 1e-12);
    s.trial_time = std::sqrt(2.0 * s.failure_displacement / (s.detect_acceleration * g));
    // A static trial relaxes at the pace the consolidation settled at, in steps: at least
    // relaxations_per_trial e-folds of it (docs/factor-of-safety.md, section 1).
    const double dt = shortest_time_step(consolidated.control.time_steps);
    s.trial_time = std::max(s.trial_time, s.relaxations_per_trial * relaxation_steps * dt);
  }
  if (s.decay_horizon_steps <= 0.0 && relaxation_steps > 0.0) {
    s.decay_horizon_steps = s.relaxations_per_trial * relaxation_steps;
  }
  return s;
}

namespace {

// The trial's world: the consolidated one with no stages (their gravity and joints have done
// their work), the last time steps the consolidation used, the trial's dynamic coefficient,
// the reduced strengths, and every block at rest.
World trial_world(const World& consolidated, const FosSettings& s, double factor) {
  World w = consolidated;
  w.stages = StagePlan{};
  w.base_motion.reset();  // a strength-reduction trial is static loading: no shaking
  w.control.dynamic_coefficient = s.dynamic_coefficient;
  w.control.steps.reset();
  w.control.end_time = consolidated.time + s.trial_time;
  w.joint_laws.clear();
  for (const JointLaw& law : scene_joint_laws(consolidated)) {
    w.joint_laws.push_back(reduced_joint_law(law, factor));
  }
  if (s.reduce_materials) {
    // Only plastic blocks read their parameters; elastic materials have no strength.
    for (WorldMaterial& m : w.materials) m.parameters = reduced_material(m.parameters, factor);
  }
  // Every block starts the trial at rest where the consolidation left it: a consolidation
  // that ended dynamic must not hand its motion to the verdict.
  for (Block& b : w.blocks) b.velocity.setZero();
  w.step_size = StepSizeMemory{};  // nor its remembered step size: the trial starts on schedule
  return w;
}

// The verdict from how the watch stopped the trial and where its motion ended.
void judge(TrialResult& r, const FosSettings& s, TrialStop stopped) {
  r.stable = false;
  if (r.interrupted) {
    r.verdict = "interrupted";
  } else if (r.stats.diverged) {
    r.verdict = "diverged: " + r.stats.message;
  } else if (stopped == TrialStop::MovedTooFar) {
    r.verdict = "moved beyond the failure displacement";
  } else if (stopped == TrialStop::MovingFast) {
    r.verdict = "moving faster than the speed limit";
  } else if (r.end_speed > r.end_speed_limit &&
             (!r.predicted_displacement || *r.predicted_displacement > s.failure_displacement)) {
    r.verdict = "still moving at the end";
  } else if (r.end_speed > r.end_speed_limit) {
    // A damped trial still relaxing at T whose decay brings it to rest short of d
    // (TrialWatch::predicted_displacement): stable, as it would be after a longer trial.
    r.stable = true;
    r.verdict = "coming to rest short of the failure displacement";
  } else {
    r.stable = true;
    r.verdict = stopped == TrialStop::AtRest ? "at rest" : "did not fail within the trial time";
  }
}

// Watched points are the free blocks in order (no monitors): the ordinal back to the block
// index.
int block_of_watched_point(const World& w, int ordinal) {
  int k = 0;
  for (std::size_t i = 0; i < w.blocks.size(); ++i) {
    if (w.blocks[i].fixed) continue;
    if (k++ == ordinal) return static_cast<int>(i);
  }
  return ordinal;
}

}  // namespace

TrialResult run_trial(const World& consolidated, const FosSettings& s, double factor,
                      const StopQuery& stop) {
  assert(s.failure_displacement > 0.0 && s.trial_time > 0.0);
  const auto start = std::chrono::steady_clock::now();
  TrialResult r;
  r.factor = factor;
  r.world = trial_world(consolidated, s, factor);
  World& w = r.world;

  // A step count far beyond what the trial time needs (step cuts shorten steps) bounds the
  // trial even if the time step collapses.
  const double dt = shortest_time_step(w.control.time_steps);
  const long step_cap = 20L * static_cast<long>(std::ceil(s.trial_time / dt)) + 100;
  // Speeds are taken as displacements over windows of steps (TrialWatch), not from the
  // blocks' velocities: rigid blocks on penalty springs keep vibrating at centimetres per
  // second in a slope that stands (measured on models/slope-fos.json at F = 1: 2.6 cm/s after
  // 1 s, against a creep speed of 3.5 cm/s, with 0.5 mm of displacement), and the vibration
  // averages out.
  TrialWatch watch({s.failure_displacement, s.trial_time, s.detect_acceleration,
                    s.dynamic_coefficient, consolidated.gravity.norm(),
                    std::max(0.0, s.decay_horizon_steps), dt},
                   watched_points(w));
  TrialStop stopped = TrialStop::Continue;
  RunHook hook;
  hook.after_step = [&](const World&, const RunStats&) {
    ++r.steps;
    if (stop && stop()) {
      r.interrupted = true;
      return false;
    }
    r.kinetic_peak = std::max(r.kinetic_peak, total_kinetic(w));
    stopped = watch.observe(watched_points(w), w.time - consolidated.time, r.steps);
    return stopped == TrialStop::Continue && r.steps < step_cap;
  };
  // The ordinary run loop (solver/run.hpp) runs the trial; the verdict watches its steps.
  r.stats = run(w, hook);
  r.kinetic_end = total_kinetic(w);
  r.simulated_time = w.time - consolidated.time;
  r.largest_displacement = watch.largest_displacement();
  r.watched_point = watch.watched_point();
  const std::vector<Vec2> end_points = watched_points(w);
  const SpeedWindow end = watch.end_speed(end_points, r.simulated_time, r.steps);
  r.end_speed = end.speed;
  r.end_speed_limit = end.limit;
  r.predicted_displacement = watch.predicted_displacement(end_points, r.simulated_time, r.steps);
  judge(r, s, stopped);
  if (w.monitors.empty() && r.watched_point >= 0) {
    r.watched_point = block_of_watched_point(w, r.watched_point);
  }
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::vector<TrialResult> run_trials(const World& consolidated, const FosSettings& s,
                                    const std::vector<double>& factors,
                                    const std::function<void(const TrialResult&)>& done,
                                    const StopQuery& stop) {
  std::vector<TrialResult> results(factors.size());
  std::mutex report;
  std::size_t next = 0;
  // Each worker takes the next factor; a trial owns its copy of the world, and the solver
  // keeps no state between worlds, so trials need nothing shared but the queue.
  auto worker = [&] {
    for (;;) {
      std::size_t k = 0;
      {
        const std::lock_guard<std::mutex> lock(report);
        if (next >= factors.size()) return;
        k = next++;
      }
      TrialResult r;
      if (stop && stop()) {
        r.factor = factors[k];
        r.interrupted = true;
        r.verdict = "interrupted";
      } else {
        r = run_trial(consolidated, s, factors[k], stop);
      }
      const std::lock_guard<std::mutex> lock(report);
      if (done) done(r);
      results[k] = std::move(r);
    }
  };
  const std::size_t threads =
      std::min<std::size_t>(factors.size(), static_cast<std::size_t>(std::max(1, s.jobs)));
  std::vector<std::thread> pool;
  for (std::size_t i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return results;
}

std::vector<double> next_factors(const std::vector<TrialResult>& trials, const FosSettings& s) {
  const int jobs = std::max(1, s.jobs);
  std::vector<double> out;
  auto add = [&](double f) {
    f = std::clamp(f, s.min_factor, s.max_factor);
    for (const TrialResult& t : trials) {
      if (t.factor == f) return;
    }
    if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
  };
  // The guess goes first when the search would double (or halve) past it, and each round
  // is filled up to `jobs` trials with the doublings (halvings). Without a guess: 1, 2, 4...
  const double guess = s.first_failing_guess;
  const bool has_guess = guess > s.min_factor && guess < s.max_factor;
  const auto fill = [&](double from, double ratio) {
    for (int k = 1; static_cast<int>(out.size()) < jobs && k <= 60; ++k) {
      add(from * std::pow(ratio, k));
    }
  };
  if (trials.empty()) {
    add(1.0);
    if (has_guess) add(guess);
    fill(1.0, 2.0);
    return out;
  }
  const Bracket b = bracket_of(trials);
  if (b.stable && b.failing) {
    const double lo = *b.stable, hi = *b.failing;
    if (hi - lo <= s.tolerance) return {};
    for (int k = 1; k <= jobs; ++k) add(lo + (hi - lo) * k / (jobs + 1));
  } else if (b.stable) {
    if (has_guess && guess > *b.stable) add(guess);
    fill(*b.stable, 2.0);
  } else {
    if (has_guess && guess < *b.failing) add(guess);
    fill(*b.failing, 0.5);
  }
  return out;
}

FosResult find_factor_of_safety(const FosSettings& s, const TrialEvaluator& evaluate) {
  std::vector<TrialResult> trials;
  bool interrupted = false;
  for (;;) {
    const std::vector<double> factors = next_factors(trials, s);
    if (factors.empty()) break;
    for (TrialResult& t : evaluate(factors)) {
      interrupted = interrupted || t.interrupted;
      trials.push_back(std::move(t));
    }
    if (interrupted) break;
  }
  return conclude_search(std::move(trials), interrupted, s);
}

FosResult conclude_search(std::vector<TrialResult> trials, bool interrupted, const FosSettings& s) {
  FosResult result;
  result.trials = std::move(trials);
  result.interrupted = interrupted;
  const Bracket b = bracket_of(result.trials);
  if (result.interrupted) {
    long judged = 0;
    for (const TrialResult& t : result.trials) judged += t.interrupted ? 0 : 1;
    result.message = "after " + std::to_string(judged) + " judged trials";
    if (b.stable && b.failing) {
      result.has_bracket = true;
      result.last_stable = *b.stable;
      result.first_failing = *b.failing;
      result.message += "; the factor lies in their bracket [" + std::to_string(*b.stable) +
                        ", " + std::to_string(*b.failing) + "], not yet as narrow as the tolerance";
    }
    return result;
  }
  if (b.stable && b.failing) {
    result.found = true;
    result.has_bracket = true;
    result.last_stable = *b.stable;
    result.first_failing = *b.failing;
    result.factor_of_safety = 0.5 * (*b.stable + *b.failing);
    if (!b.monotone) {
      // Where: every stable trial above the lowest failing one, named by its F.
      std::string above;
      for (const TrialResult& t : result.trials) {
        if (t.interrupted || !t.stable || t.factor < *b.failing) continue;
        char f[32];
        std::snprintf(f, sizeof f, "%.4f", t.factor);
        above += (above.empty() ? "" : ", ") + std::string(f);
      }
      char failing[32];
      std::snprintf(failing, sizeof failing, "%.4f", *b.failing);
      result.message = "the verdicts are not monotone in F: stable at F = " + above +
                       ", above the failing F = " + failing +
                       " (the bracket is the lowest failing factor and the stable one below it): "
                       "near its factor a slope's trials are decided by which contacts slip "
                       "first, which changes F in its sixth digit can change, so the factor is "
                       "known to the width of that band (docs/factor-of-safety.md, section 6)";
    }
  } else if (b.stable) {
    result.message = "no trial failed up to F = " + std::to_string(s.max_factor) +
                     ": the scene is stable beyond the search range (raise --max-factor)";
  } else {
    result.message = "every trial failed down to F = " + std::to_string(s.min_factor) +
                     ": the scene is not stable even with its full strength (did its "
                     "consolidation come to rest?)";
  }
  return result;
}

}  // namespace dda
