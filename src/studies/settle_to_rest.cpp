#include "studies/settle_to_rest.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "solver/run.hpp"
#include "studies/recent_motion.hpp"

namespace dda {
namespace {

// The window the ratio is read over, and the at-rest test's: the trial's (studies/trial_watch.cpp).
constexpr int kSettleRestSteps = 20;
// The creep test: over windows of this many steps, the window's largest ratio did not fall
// below kCreepShare of the window before, kCreepWindows times in a row. A model relaxing
// with an e-fold of n steps falls by exp(-50 / n) a window: 0.95 at n = 1000 (the vertical
// cut's soil at dt 0.002 s), 0.99 only beyond n = 5000 steps; a block creeping at a steady
// pace does not fall at all.
constexpr int kCreepWindow = 50;
constexpr double kCreepShare = 0.99;
constexpr int kCreepWindows = 3;
// A pace measured over fewer steps than this is no pace: the first steps after a load carry
// the fast modes too (they fall within a few steps), and a settling this short needs none.
constexpr int kPaceSteps = 100;

double window_mean(const std::vector<double>& r, std::size_t from, std::size_t count) {
  return std::accumulate(r.begin() + static_cast<long>(from),
                         r.begin() + static_cast<long>(from + count), 0.0) /
         static_cast<double>(count);
}

}  // namespace

double unbalanced_ratio(double largest_step_displacement, double gravity, double dt) {
  const double unit = 0.5 * gravity * dt * dt;
  return unit > 0.0 ? largest_step_displacement / unit : 0.0;
}

double relaxation_steps_of(const std::vector<double>& ratios) {
  const std::size_t n = ratios.size();
  constexpr std::size_t w = kSettleRestSteps;
  if (n < static_cast<std::size_t>(kPaceSteps)) return 0.0;
  const std::size_t a = n / 4;
  const std::size_t b = n - w;
  const double ra = window_mean(ratios, a, w);
  const double rb = window_mean(ratios, b, w);
  if (!(ra > rb) || rb <= 0.0) return 0.0;
  return static_cast<double>(b - a) / std::log(ra / rb);
}

Settling settle_to_rest(World& world, const SettlingSettings& s,
                        const std::function<bool()>& keep_going) {
  Settling out;
  const StagePlan stages = world.stages;
  const ControlSettings control = world.control;
  // The world's present gravity, joint laws and time steps: those the consolidation ended
  // with (a stage's, when it has stages). Without the plan, no stage changes them.
  world.stages = StagePlan{};
  world.control.dynamic_coefficient = 0.0;
  world.control.steps.reset();
  const double dt_max = *std::max_element(world.control.time_steps.begin(),
                                          world.control.time_steps.end());
  world.control.end_time = world.time + (s.max_steps + 1.0) * dt_max;
  for (Block& b : world.blocks) b.velocity.setZero();

  const double g = world.gravity.norm();
  // Each step's ratio is read over the window of the last kSettleRestSteps steps (fewer at
  // the start): a contact that chatters moves a block back and forth from step to step with
  // no net motion (measured: the vertical cut at a tenth of the auto penalty, 0.08 g a step
  // and no net displacement), as the trial's own at-rest test sees it (studies/trial_watch).
  RecentMotion recent(kSettleRestSteps, MotionMark{free_block_centroids(world), world.time, 0});
  std::vector<double> ratios;
  int flat = 0;         // creep windows in a row that did not fall
  double last_window = 0.0;
  RunHook hook;
  hook.after_step = [&](const World& w, const RunStats&) {
    const std::size_t n = ratios.size() + 1;  // steps so far
    MotionMark now{free_block_centroids(w), w.time, static_cast<long>(n)};
    const MotionMark& from = recent.window_start(now.step);
    const auto window = static_cast<double>(now.step - from.step);  // n, at most 20
    const double largest = farthest_motion(from.points, now.points);
    const double mean_dt = (now.time - from.time) / window;
    const double r = unbalanced_ratio(largest / window, g, mean_dt);
    ratios.push_back(r);
    recent.record(std::move(now));
    if (n >= static_cast<std::size_t>(kSettleRestSteps) && r < s.rest_ratio) {
      out.at_rest = true;
      out.stopped = "at rest";
      return false;
    }
    if (n % kCreepWindow == 0) {
      const double window_max = *std::max_element(ratios.end() - kCreepWindow, ratios.end());
      flat = (last_window > 0.0 && window_max >= kCreepShare * last_window) ? flat + 1 : 0;
      last_window = window_max;
      if (flat >= kCreepWindows) {
        out.stopped = "not settling";
        return false;
      }
    }
    if (static_cast<int>(n) >= s.max_steps) {
      out.stopped = "step cap";
      return false;
    }
    return !keep_going || keep_going();
  };
  out.stats = run(world, hook);
  if (out.stats.diverged) out.stopped = "diverged: " + out.stats.message;
  if (out.stopped.empty()) out.stopped = "interrupted";
  out.steps = static_cast<int>(ratios.size());
  if (!ratios.empty()) {
    out.unbalanced_start = ratios.front();
    out.unbalanced_end = ratios.back();
  }
  // The pace only from a settling that came to rest: creep or a cap leaves no decay to read.
  if (out.at_rest) out.relaxation_steps = relaxation_steps_of(ratios);
  world.stages = stages;
  world.control = control;
  return out;
}

}  // namespace dda
