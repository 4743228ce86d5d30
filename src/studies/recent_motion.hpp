// The watched points' positions over the last few steps of a run, so that a speed can be read
// as a net displacement over a window of steps rather than from one step: a contact that
// chatters moves a block back and forth with no net motion, and rigid blocks on penalty
// springs vibrate in a slope that stands. The strength-reduction verdict (trial_watch) and
// the consolidation's settling (settle_to_rest) read their at-rest tests from it.
#pragma once

#include <cstddef>
#include <vector>

#include "kinematics/types.hpp"
#include "solver/world.hpp"

namespace dda {

// Where the watched points were after a step: the step's number since the watch began (0:
// the start), the time since then (s) and the sum of the squared step lengths since then
// (s^2: a static step relaxes a mode by a share that goes as dt^2, so this is the
// relaxation's own clock when steps are cut).
struct MotionMark {
  std::vector<Vec2> points;
  double time = 0.0;
  long step = 0;
  double relaxation_clock = 0.0;
};

// The farthest any point moved from `from` to `to` (m); the two have the same points.
double farthest_motion(const std::vector<Vec2>& from, const std::vector<Vec2>& to);

// The centroids of the free blocks, in block order: the points a study watches when the
// scene names none.
std::vector<Vec2> free_block_centroids(const World& world);

// A ring of the marks of the last `window` steps, recorded one a step.
class RecentMotion {
 public:
  RecentMotion(std::size_t window, MotionMark start);

  // The mark the window ending at step `step` starts from: the mark `window` steps before
  // (window - 1 when step's own mark was recorded already), or the start while the run has
  // had no more than `window` steps.
  const MotionMark& window_start(long step) const;
  void record(MotionMark mark);
  std::size_t window() const { return ring_.size(); }

 private:
  MotionMark start_;
  std::vector<MotionMark> ring_;  // the mark of step s in slot s % window
};

}  // namespace dda
