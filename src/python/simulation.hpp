// A scene's run driven from Python a few steps at a time (dda.Simulation): the world, the
// step loop's workspace kept between calls so that the steps are those of one run, and
// what the run has counted. Every step goes through solver/run.hpp's loop. No Python here:
// the bindings (module.cpp) release the GIL around these calls.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/output.hpp"
#include "python/signal_watch.hpp"
#include "solver/run.hpp"
#include "solver/scene.hpp"
#include "solver/step.hpp"
#include "solver/world.hpp"

namespace dda::python {

// A step failed (the run diverged): dda.DivergedError. The world keeps the last good step.
class DivergedRun : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Simulation {
 public:
  explicit Simulation(Scene scene);

  // Up to `steps` more steps, fewer at the scene's end or when `stop` asks; the steps made.
  // Throws DivergedRun when a step fails (and on every call after it).
  int step(int steps, const StopQuery& stop);

  // Steps until the time reaches `until` (s; the first step at or past it), or to the
  // scene's end when none is given; the steps made. `writer` (may be null) records as
  // `dda run` does: the start when no step was made yet, every control.output_every-th step,
  // the last one, and where a failed or stopped run ended; then its summary. Throws
  // DivergedRun after recording.
  int run(std::optional<double> until, const StopQuery& stop, OutputWriter* writer = nullptr);

  // The scene's end reached (its steps or end time, and its last stage).
  bool finished() const;

  const Scene& scene() const { return scene_; }
  const World& world() const { return world_; }
  const RunStats& stats() const { return stats_; }
  double wall_time_s() const { return wall_time_s_; }

  // Set while a call steps it (the bindings' guard against a second thread).
  mutable std::atomic<bool> busy{false};

 private:
  // Runs steps until `reached` says so after one (or the scene ends, or `stop` asks).
  int advance(const std::function<bool(const World&)>& reached, const StopQuery& stop,
              const std::function<void(const World&)>& after_step);
  void throw_if_diverged() const;

  Scene scene_;
  World world_;
  std::unique_ptr<StepWorkspace> workspace_;
  RunStats stats_;
  double wall_time_s_ = 0.0;  // over every call; RunStats::wall_time_s is the last call's
  std::string diverged_;      // the failed step's message; empty while the run goes on
};

}  // namespace dda::python
