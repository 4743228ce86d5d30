#include "treatments.hpp"

#include <limits>
#include <chrono>
#include <exception>
#include <stdexcept>

#include "solver/step.hpp"

namespace dda::paper {

std::vector<Treatment> treatments_for(bool smoke) {
  if (!smoke) return all_treatments();
  std::vector<Treatment> picked;
  for (const Treatment& t : all_treatments()) {
    if (t.name == "original" || t.name == "local_frame" || t.name == "finite_rotation") {
      picked.push_back(t);
    }
  }
  return picked;
}

std::string_view status_word(RunStatus s) {
  switch (s) {
    case RunStatus::Completed: return "completed";
    case RunStatus::Diverged: return "diverged";
  }
  return "?";
}

RunResult run_world(World& world, const Observer& observe) {
  RunResult result;
  StepWorkspace ws;
  const auto start = std::chrono::steady_clock::now();
  // The reproduction measures how much energy each treatment creates: the energy guard,
  // which would stop such a run, is off here.
  world.control.energy_tolerance = std::numeric_limits<double>::infinity();
  try {
    observe(world);
    while (!is_finished(world)) {
      const StepOutcome outcome = advance_step(world, ws, result.stats);
      if (!outcome.ok) {
        result.status = RunStatus::Diverged;
        result.message = outcome.message;
        break;
      }
      observe(world);
    }
  } catch (const std::exception& e) {
    result.status = RunStatus::Diverged;
    result.message = e.what();
  }
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.steps_done = world.step;
  result.stats.steps = world.step;
  return result;
}

std::string describe(const RunResult& r) {
  switch (r.status) {
    case RunStatus::Completed: return "completed";
    case RunStatus::Diverged:
      // The step's own messages already start "step k (t = ...): ..."; others do not.
      if (r.message.rfind("step ", 0) == 0) return "diverged at " + r.message;
      return "diverged at step " + std::to_string(r.steps_done + 1) + ": " + r.message;
  }
  return "?";
}

}  // namespace dda::paper
