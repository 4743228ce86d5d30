// The time loop: advances a World step by step until the scene's steps or end time. The
// world's own stages (solver/stages.hpp) are entered and their gravity set between steps;
// whatever else a caller changes between steps (a moving anchor, a pushed platen) and what
// it watches after each step (output, a verdict, a stop) pass through a RunHook, so that
// every driver of the step is this one loop.
#pragma once

#include <functional>
#include <string>

#include "solver/run_stats.hpp"
#include "solver/world.hpp"

namespace dda {

// What a caller does around the steps of run(). Every member may be empty.
struct RunHook {
  // Once before the first step (world.step == 0). Return false to run no step.
  std::function<bool(const World&, const RunStats&)> at_start;
  // Between steps, once the stage's settings are in and before the step: changes the world
  // the coming step reads. A change that does work on the scene books it as load work
  // (World::energy), so that the energy account and its guard see it.
  std::function<void(World&)> before_step;
  // After each completed step. Return false to stop the run (RunStats::interrupted when the
  // scene had not finished).
  std::function<bool(const World&, const RunStats&)> after_step;
};

// Runs `world` to its end, a failed step or a hook's stop, counting into `stats` (which
// keeps what the steps counted so far should a step throw).
void run(World& world, const RunHook& hook, RunStats& stats);
RunStats run(World& world, const RunHook& hook);

// Called with the world after each completed step (and once before the first step with
// world.step == 0). Return false to stop the run.
using StepObserver = std::function<bool(const World&, const RunStats&)>;

// run() with `observe` at the start and after every step.
RunStats run(World& world, const StepObserver& observe);

}  // namespace dda
