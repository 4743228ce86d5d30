#include "solver/run.hpp"

#include <chrono>

#include "solver/step.hpp"

namespace dda {

RunStats run(World& world, const StepObserver& observe) {
  const auto start = std::chrono::steady_clock::now();
  RunStats stats;
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  StepWorkspace ws;
  bool keep_going = observe(world, stats);
  while (keep_going && !is_finished(world)) {
    const StepOutcome outcome = advance_step(world, ws, stats);
    stats.steps = world.step;
    stats.wall_time_s = elapsed();
    if (!outcome.ok) {
      stats.diverged = true;
      stats.message = outcome.message;
      break;
    }
    keep_going = observe(world, stats);
  }
  stats.wall_time_s = elapsed();
  return stats;
}

}  // namespace dda
