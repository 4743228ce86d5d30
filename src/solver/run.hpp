// The time loop: advances a World step by step until the scene's steps or end time,
// reporting to an observer after every completed step.
#pragma once

#include <functional>
#include <string>

#include "solver/run_stats.hpp"
#include "solver/world.hpp"

namespace dda {

// Called with the world after each completed step (and once before the first step with
// world.step == 0). Return false to stop the run.
using StepObserver = std::function<bool(const World&, const RunStats&)>;

RunStats run(World& world, const StepObserver& observe);

}  // namespace dda
