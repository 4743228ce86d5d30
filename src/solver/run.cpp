#include "solver/run.hpp"

#include <chrono>

#include "solver/stages.hpp"
#include "solver/step.hpp"

namespace dda {

void run(World& world, const RunHook& hook, RunStats& stats) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  StepWorkspace ws;
  bool keep_going = !hook.at_start || hook.at_start(world, stats);
  while (keep_going) {
    // Stages (solver/stages.hpp): at the end of one the next takes over, and forms its bonds
    // on the contacts closed now. Without stages the run ends with control's end.
    while (enter_next_stage(world, world.contacts)) {
    }
    if (is_finished(world)) break;
    set_stage_gravity(world);  // a ramp's gravity at this step's end; no stages: unchanged
    if (hook.before_step) hook.before_step(world);
    const StepOutcome outcome = advance_step(world, ws, stats);
    stats.steps = world.step;
    stats.wall_time_s = elapsed();
    if (!outcome.ok) {
      stats.diverged = true;
      stats.message = outcome.message;
      break;
    }
    keep_going = !hook.after_step || hook.after_step(world, stats);
    if (!keep_going && !is_finished(world)) stats.interrupted = true;
  }
  stats.wall_time_s = elapsed();
}

RunStats run(World& world, const RunHook& hook) {
  RunStats stats;
  run(world, hook, stats);
  return stats;
}

RunStats run(World& world, const StepObserver& observe) {
  return run(world, RunHook{observe, {}, observe});
}

}  // namespace dda
