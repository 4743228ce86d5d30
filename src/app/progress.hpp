// A one-line progress bar on stderr for interactive runs. Silent when stderr is not a
// terminal (pipes, log files, CI), so that redirected output stays clean.
#pragma once

#include <chrono>
#include <string>

#include "solver/scene.hpp"
#include "solver/world.hpp"

namespace dda {

// A run's progress in the unit its bar counts: completed steps when the scene gives
// control.steps, else simulated seconds up to its end time.
inline double run_length(const Scene& scene) {
  return scene.control.steps ? static_cast<double>(*scene.control.steps) : *scene.control.end_time;
}
inline double run_position(const Scene& scene, const World& world) {
  return scene.control.steps ? static_cast<double>(world.step) : world.time;
}
inline const char* run_unit(const Scene& scene) { return scene.control.steps ? "steps" : "s"; }

class ProgressBar {
 public:
  // `end` is the value that means done (e.g. the end time or the step count); values start
  // at 0. `label` is printed in front of the bar.
  ProgressBar(double end, std::string label);
  ~ProgressBar();

  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Reports the current value. Redraws at most about 10 times per second.
  void update(double value);

  // Draws the final state and ends the line. Further calls do nothing.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;

  void draw();

  double end_;
  std::string label_;
  double value_ = 0.0;
  bool enabled_;          // stderr is a terminal
  bool drawn_ = false;    // something is on the line, so it needs ending
  bool finished_ = false;
  Clock::time_point start_;
  Clock::time_point last_draw_;
};

}  // namespace dda
