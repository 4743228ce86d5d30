#include "studies/strength_reduction.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>

#include "solver/run.hpp"
#include "solver/step.hpp"

namespace dda {
namespace {

// The at-rest test of a trial (run_trial): over a window of this many steps, every watched
// point moved at less than this share of the speed limit (d / T in a dynamic trial).
constexpr int kRestSteps = 20;
constexpr double kRestSpeedShare = 0.01;
// A damped trial fails early when, after half its time, a watched point moved over the
// trial's last quarter at more than this multiple of the speed limit.
constexpr double kFailSpeedShare = 4.0;

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
  for (const Block& b : w.blocks) {
    if (!b.fixed) out.push_back(b.moments.centroid);
  }
  return out;
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
  r.tan_phi = law.tan_phi / factor;
  r.cohesion = law.cohesion / factor;
  r.tensile_strength = law.tensile_strength / factor;
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
  Consolidation out{make_world(stronger), {}};
  out.stats = run(out.world, observe);
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

FosSettings resolve_fos_settings(const World& consolidated, FosSettings s) {
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
  }
  return s;
}

TrialResult run_trial(const World& consolidated, const FosSettings& s, double factor,
                      const StopQuery& stop) {
  assert(s.failure_displacement > 0.0 && s.trial_time > 0.0);
  const auto start = std::chrono::steady_clock::now();
  TrialResult r;
  r.factor = factor;
  r.world = consolidated;
  World& w = r.world;
  // The trial: no stages (their gravity and joints have done their work); the last time
  // steps the consolidation used, the trial's dynamic coefficient, the reduced strengths.
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

  const std::vector<Vec2> start_points = watched_points(w);
  // A step count far beyond what the trial time needs (step cuts shorten steps) bounds the
  // trial even if the time step collapses.
  const double dt = *std::min_element(w.control.time_steps.begin(), w.control.time_steps.end());
  const long step_cap = 20L * static_cast<long>(std::ceil(s.trial_time / dt)) + 100;
  StepWorkspace ws;
  RunStats stats;
  bool moved_too_far = false, at_rest = false, moving_fast = false;
  // In a dynamic trial, a point still moving faster than d / T would pass the failure
  // displacement within another trial time: the slope has not come to rest, it is failing
  // slowly. Speeds are taken as displacements over a window of steps, not from the blocks'
  // velocities: rigid blocks on penalty springs keep vibrating at centimetres per second in
  // a slope that stands (measured on models/slope-fos.json at F = 1: 2.6 cm/s after 1 s,
  // against a creep speed of 3.5 cm/s, with 0.5 mm of displacement), and the vibration
  // averages out.
  // A damped trial (dynamic coefficient k < 1) carries only k of each step's velocity, so a
  // mechanism whose out-of-balance force accelerates it at a settles to a steady speed: per
  // step v' = k v + a dt, hence v = a dt / (1 - k), and a mean speed over the step of
  // a dt (1 + k) / (2 (1 - k)) (a dt / 2 from rest in a static trial, k = 0). Its speed
  // limit is that of a mechanism at detect_acceleration g, over the window's mean step.
  const double creep_speed = s.failure_displacement / s.trial_time;
  const double k = s.dynamic_coefficient;
  const double g = consolidated.gravity.norm();
  const auto speed_limit = [&](double window_time, long window_steps) {
    if (k >= 1.0 || window_steps <= 0) return creep_speed;
    const double mean_dt = window_time / static_cast<double>(window_steps);
    return s.detect_acceleration * g * mean_dt * (1.0 + k) / (2.0 * (1.0 - k));
  };
  // Where the watched points were at a step (time since the trial started, step count):
  // speeds are taken from such a mark to the present. Marks of the last kRestSteps steps (a
  // ring), of the step a quarter of the trial time before its end, and of the start.
  struct Mark {
    std::vector<Vec2> points;
    double time = 0.0;
    long step = 0;
  };
  struct Window {
    double speed = 0.0;  // m/s, the fastest watched point's displacement over the time
    double limit = 0.0;  // m/s, speed_limit over the same window
  };
  const auto since = [&](const Mark& from, const std::vector<Vec2>& to, double time, long step) {
    const double span = time - from.time;
    double fastest = 0.0;
    for (std::size_t i = 0; i < from.points.size(); ++i) {
      fastest = std::max(fastest, (to[i] - from.points[i]).norm());
    }
    return Window{span > 0.0 ? fastest / span : 0.0, speed_limit(span, step - from.step)};
  };
  const Mark at_start{start_points, 0.0, 0};
  std::vector<Mark> ring(kRestSteps);
  std::optional<Mark> late;
  // The marks of the last quarter of the trial time (oldest first), for the early failure.
  std::deque<Mark> quarter{at_start};
  while (!is_finished(w) && r.steps < step_cap) {
    const StepOutcome outcome = advance_step(w, ws, stats);
    if (!outcome.ok) {
      r.verdict = "diverged: " + outcome.message;
      break;
    }
    ++r.steps;
    if (stop && stop()) {
      r.interrupted = true;
      break;
    }
    const std::vector<Vec2> now = watched_points(w);
    const double elapsed = w.time - consolidated.time;
    for (std::size_t i = 0; i < start_points.size(); ++i) {
      const double u = (now[i] - start_points[i]).norm();
      if (u > r.largest_displacement) {
        r.largest_displacement = u;
        r.watched_point = static_cast<int>(i);
      }
    }
    r.kinetic_peak = std::max(r.kinetic_peak, total_kinetic(w));
    if (r.largest_displacement > s.failure_displacement) {
      moved_too_far = true;
      break;
    }
    if (!late && elapsed >= 0.75 * s.trial_time) late = Mark{now, elapsed, r.steps};
    // At rest: after a quarter of the trial time, every watched point moved over the last
    // kRestSteps steps at less than 1 % of the speed limit. The rest of the trial would
    // repeat the same state.
    const std::size_t slot = static_cast<std::size_t>(r.steps % kRestSteps);
    std::optional<Window> recent;
    if (r.steps > kRestSteps) recent = since(ring[slot], now, elapsed, r.steps);
    if (recent && elapsed >= 0.25 * s.trial_time && recent->speed < kRestSpeedShare * recent->limit) {
      at_rest = true;
      break;
    }
    // A damped trial has no inertia to carry it through a pause: a mechanism that moved at
    // several times the limit over a whole quarter of the trial time, half of it gone, and
    // still moves faster than the limit over its last 20 steps, is failing, and the rest of
    // the trial would only repeat that. A shorter window (the last 20 steps alone) called
    // transients failing: when the reduced strengths first act, load passes from the
    // contacts that slip to their neighbours, and a soft penalty lets a group move a
    // millimetre at 10 to 60 times the limit for a few tenths of a second before it comes to
    // rest (verification/slope-cut, 652 blocks, penalty auto / 10: 0.58 mm over 0.8 s at
    // F = 0.92, then at rest; the short window gave F = 0.910). The long window alone called
    // a transient failing that had died down at T/2 (the steep slope at dt 0.002, F = 0.578:
    // 2e-6 m/s over the last 20 steps against a limit of 2e-5).
    if (k < 1.0) {
      while (quarter.size() > 1 && quarter[1].time <= elapsed - 0.25 * s.trial_time) {
        quarter.pop_front();
      }
      if (recent && elapsed >= 0.5 * s.trial_time && recent->speed > recent->limit) {
        const Window last_quarter = since(quarter.front(), now, elapsed, r.steps);
        if (last_quarter.speed > kFailSpeedShare * last_quarter.limit) {
          moving_fast = true;
          break;
        }
      }
      quarter.push_back(Mark{now, elapsed, r.steps});
    }
    ring[slot] = Mark{now, elapsed, r.steps};
  }
  const std::vector<Vec2> end = watched_points(w);
  r.kinetic_end = total_kinetic(w);
  r.simulated_time = w.time - consolidated.time;
  // The end speed: over the trial's last quarter (or over the last kRestSteps steps when it
  // stopped at rest or early).
  const Mark* from = nullptr;
  if (late && r.simulated_time > late->time) {
    from = &*late;
  } else if (r.steps > kRestSteps) {
    from = &ring[static_cast<std::size_t>(r.steps % kRestSteps)];
  } else if (r.simulated_time > 0.0) {
    from = &at_start;
  }
  if (from != nullptr) {
    const Window last = since(*from, end, r.simulated_time, r.steps);
    r.end_speed = last.speed;
    r.end_speed_limit = last.limit;
  }
  if (r.interrupted) {
    r.stable = false;
    r.verdict = "interrupted";
  } else if (!r.verdict.empty()) {
    r.stable = false;  // diverged
  } else if (moved_too_far) {
    r.stable = false;
    r.verdict = "moved beyond the failure displacement";
  } else if (moving_fast) {
    r.stable = false;
    r.verdict = "moving faster than the speed limit";
  } else if (r.end_speed > r.end_speed_limit) {
    r.stable = false;
    r.verdict = "still moving at the end";
  } else {
    r.stable = true;
    r.verdict = at_rest ? "at rest" : "did not fail within the trial time";
  }
  if (w.monitors.empty() && r.watched_point >= 0) {
    // Watched points are the free blocks in order: the ordinal back to the block index.
    int ordinal = 0;
    for (std::size_t i = 0; i < w.blocks.size(); ++i) {
      if (w.blocks[i].fixed) continue;
      if (ordinal++ == r.watched_point) {
        r.watched_point = static_cast<int>(i);
        break;
      }
    }
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
  if (trials.empty()) {
    for (int k = 0; k < jobs; ++k) add(std::ldexp(1.0, k));  // 1, 2, 4, ...
    return out;
  }
  const Bracket b = bracket_of(trials);
  if (b.stable && b.failing) {
    const double lo = *b.stable, hi = *b.failing;
    if (hi - lo <= s.tolerance) return {};
    for (int k = 1; k <= jobs; ++k) add(lo + (hi - lo) * k / (jobs + 1));
  } else if (b.stable) {
    for (int k = 1; k <= jobs; ++k) add(*b.stable * std::ldexp(1.0, k));
  } else {
    for (int k = 1; k <= jobs; ++k) add(*b.failing * std::ldexp(1.0, -k));
  }
  return out;
}

FosResult find_factor_of_safety(const FosSettings& s, const TrialEvaluator& evaluate) {
  FosResult result;
  for (;;) {
    const std::vector<double> factors = next_factors(result.trials, s);
    if (factors.empty()) break;
    for (TrialResult& t : evaluate(factors)) {
      result.interrupted = result.interrupted || t.interrupted;
      result.trials.push_back(std::move(t));
    }
    if (result.interrupted) break;
  }
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
                       " (the bracket is the lowest failing factor and the stable one below it)";
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
