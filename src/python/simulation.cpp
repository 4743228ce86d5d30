#include "python/simulation.hpp"

#include <utility>

namespace dda::python {

Simulation::Simulation(Scene scene)
    : scene_(std::move(scene)), world_(make_world(scene_)), workspace_(std::make_unique<StepWorkspace>()) {}

bool Simulation::finished() const {
  const StagePlan& plan = world_.stages;
  const bool last_stage = plan.current < 0 || plan.current + 1 >= static_cast<int>(plan.stages.size());
  return last_stage && is_finished(world_);
}

void Simulation::throw_if_diverged() const {
  if (!diverged_.empty()) throw DivergedRun("the run diverged at " + diverged_);
}

int Simulation::advance(const std::function<bool(const World&)>& reached, const StopQuery& stop,
                        const std::function<void(const World&)>& after_step) {
  throw_if_diverged();
  const int before = world_.step;
  RunHook hook;
  hook.after_step = [&](const World& w, const RunStats&) {
    if (after_step) after_step(w);
    return !reached(w) && !(stop && stop());
  };
  dda::run(world_, *workspace_, hook, stats_);
  wall_time_s_ += stats_.wall_time_s;
  if (stats_.diverged) diverged_ = stats_.message;
  return world_.step - before;
}

int Simulation::step(int steps, const StopQuery& stop) {
  if (steps <= 0 || finished()) {
    throw_if_diverged();
    return 0;
  }
  const int target = world_.step + steps;
  const int made = advance([target](const World& w) { return w.step >= target; }, stop, {});
  stats_.interrupted = false;  // stopping after the steps asked for is no interruption
  throw_if_diverged();
  return made;
}

int Simulation::run(std::optional<double> until, const StopQuery& stop, OutputWriter* writer) {
  throw_if_diverged();
  const auto reached = [until](const World& w) { return until && w.time >= *until; };
  if (writer && world_.step == 0) writer->record(world_);
  int made = 0;
  if (!reached(world_) && !finished()) {
    made = advance(reached, stop, [&](const World& w) {
      if (writer) writer->record_if_due(w);
    });
  }
  if (writer) {
    // A run stopped by a signal or a failed step keeps its last state, as dda run's does.
    if (stats_.diverged || stats_.interrupted) writer->record_last(world_);
    writer->finish(world_, stats_);
  }
  stats_.interrupted = false;
  throw_if_diverged();
  return made;
}

}  // namespace dda::python
