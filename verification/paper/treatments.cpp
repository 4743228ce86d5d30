#include "treatments.hpp"

#include <chrono>
#include <limits>
#include <exception>
#include <stdexcept>

#include "solver/run.hpp"

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

RunResult run_world(World& world, const RunHook& hook) {
  RunResult result;
  const auto start = std::chrono::steady_clock::now();
  try {
    run(world, hook, result.stats);
    if (result.stats.diverged) {
      result.status = RunStatus::Diverged;
      result.message = result.stats.message;
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

RunResult run_world(World& world, const Observer& observe) {
  // The reproduction measures how much energy each treatment creates: the energy guard,
  // which would stop such a run, is off here.
  world.control.energy_tolerance = std::numeric_limits<double>::infinity();
  const auto watch = [&observe](const World& w, const RunStats&) {
    observe(w);
    return true;
  };
  return run_world(world, RunHook{watch, {}, watch});
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
