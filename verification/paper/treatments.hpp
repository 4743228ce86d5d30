// The rotation treatments the reproduction compares, and one way to run a world with any of
// them that never throws: a failed step, or an exception, is reported as "diverged at step k".
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "solver/run.hpp"
#include "solver/scene.hpp"
#include "solver/world.hpp"

namespace dda::paper {

struct Treatment {
  std::string_view name;   // the scene name (docs/scene-format.md, "Rotation treatments")
  RotationUpdate value;
  std::string_view paper;  // the paper's row for it, empty if the paper has none
};

// Adding a treatment is one line here. Every treatment name has an enum value now; whether
// the library implements it is found out at run time (run_world), so the table need not
// change as the other engineers finish theirs.
inline const std::vector<Treatment>& all_treatments() {
  static const std::vector<Treatment> kAll = {
      {"original", RotationUpdate::Original, "Original DDA"},
      {"second_order", RotationUpdate::SecondOrder, ""},
      {"post_adjustment", RotationUpdate::PostAdjustment, "Ke"},
      {"sin_variable", RotationUpdate::SinVariable, "Cheng and Zhang"},
      {"local_frame", RotationUpdate::LocalFrame, "Proposed"},
      {"local_frame_as_printed", RotationUpdate::LocalFrameAsPrinted, ""},
      {"finite_rotation", RotationUpdate::FiniteRotation, ""},
      // The paper's method as printed (Shi's inertia, the end-of-step angle) and this code's
      // default (docs/large-strain.md).
      {"paper", RotationUpdate::Paper, ""},
      {"finite_rotation_polar", RotationUpdate::FiniteRotationPolar, ""},
  };
  return kAll;
}

// The treatments a run covers: all of them, or in smoke mode three (original and the two the
// paper recommends), to keep the CI run short.
std::vector<Treatment> treatments_for(bool smoke);

enum class RunStatus { Completed, Diverged };
std::string_view status_word(RunStatus s);

struct RunResult {
  RunStatus status = RunStatus::Completed;
  int steps_done = 0;    // completed steps
  std::string message;   // why it stopped early; empty when completed
  double wall_s = 0.0;   // wall time of the stepping alone (observer included), steady_clock
  RunStats stats;        // cuts, solves, open-close iterations
};

// Called once before the first step (world.step == 0) and after every completed step.
using Observer = std::function<void(const World&)>;

// Runs `world` (solver/run.hpp, with `hook`) until its scene is finished or a step fails.
// A std::logic_error from the library is how it says "this rotation_update is not
// implemented yet"; any other exception or a failed step is a divergence at that step.
RunResult run_world(World& world, const RunHook& hook);

// The same with the energy guard off (the reproduction measures the energy each treatment
// creates) and `observe` at the start and after every step.
RunResult run_world(World& world, const Observer& observe);

// A one-line description of a result for tables: "completed", "diverged at step 123 (...)".
std::string describe(const RunResult& r);

}  // namespace dda::paper
