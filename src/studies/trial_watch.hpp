// The verdict of a strength-reduction trial, read from where its watched points go step by
// step (docs/factor-of-safety.md, section 2). Positions and times in, verdict out: run_trial
// feeds it from the run loop's observer, and tests feed it made-up paths.
#pragma once

#include <deque>
#include <optional>
#include <vector>

#include "kinematics/types.hpp"
#include "studies/recent_motion.hpp"

namespace dda {

struct TrialWatchSettings {
  double failure_displacement = 0.0;  // m: a watched point moving farther fails the trial
  double trial_time = 0.0;            // s: T
  double detect_acceleration = 0.002; // share of |g| of the slowest mechanism resolved
  double dynamic_coefficient = 0.0;   // k: 0 static, 1 dynamic
  double gravity = 9.81;              // |g| (m/s^2)
  // A damped trial's motion counts as decaying (predicted_displacement) only if it loses 1/e
  // within this many steps of length reference_dt (s; steps cut shorter count as dt^2 /
  // reference_dt^2 of one, the share they relax by); 0: within the trial time T, in steps of
  // the last window's mean length.
  double decay_horizon_steps = 0.0;
  double reference_dt = 0.0;
};

// Why a trial stops before its time (Continue: it goes on).
enum class TrialStop {
  Continue,
  MovedTooFar,      // a watched point moved beyond the failure displacement
  AtRest,           // after T/4, every watched point still over the last 20 steps
  MovingFast,       // k < 1, after T/2: fast over the last quarter and the last 20 steps, and
                    // its decay (predicted_displacement) carries it beyond d
};

// A speed over a window of steps: the fastest watched point's displacement over the window's
// time, and the speed limit over the same window.
struct SpeedWindow {
  double speed = 0.0;  // m/s
  double limit = 0.0;  // m/s
};

class TrialWatch {
 public:
  TrialWatch(const TrialWatchSettings& settings, std::vector<Vec2> start);

  // After each step: the watched points, the time since the trial began (s) and the steps
  // since. Says whether the verdict is reached.
  TrialStop observe(const std::vector<Vec2>& now, double elapsed, long steps);

  // The end speed: over the trial's last quarter, or over the last 20 steps when it stopped
  // before that quarter began, or since the start.
  SpeedWindow end_speed(const std::vector<Vec2>& end, double elapsed, long steps) const;

  // The speed limit over a window of `window_steps` steps lasting `window_time`: d / T in a
  // dynamic trial (a point still that fast at the end would pass d within another trial
  // time: the slope is failing slowly, not at rest); in a damped one the steady speed a g dt (1 + k) / (2 (1 - k)) of a
  // mechanism accelerating at a = detect_acceleration g, over the window's mean step dt.
  double speed_limit(double window_time, long window_steps) const;

  // Where a damped trial's motion is heading (k < 1; m): the farthest displacement so far plus
  // what the fastest point still moves if its motion goes on decaying as it did over the last
  // two eighths of the trial time, by the ratio rho of the last eighth's speed to the one
  // before's (each as a multiple of its window's speed limit): a geometric series
  // m rho / (1 - rho) after the last eighth's motion m. Infinite when the motion is not
  // decaying: rho >= 1, or an e-fold longer than decay_horizon_steps (steps of reference_dt,
  // counted by the relaxation clock of MotionMark). nullopt
  // before a quarter of the trial time (no two eighths to compare) and in dynamic trials.
  std::optional<double> predicted_displacement(const std::vector<Vec2>& now, double elapsed,
                                               long steps) const;

  double largest_displacement() const { return largest_; }
  int watched_point() const { return watched_; }  // the point that moved most, -1 before any

 private:
  using Mark = MotionMark;
  SpeedWindow since(const Mark& from, const std::vector<Vec2>& to, double time, long step) const;

  TrialWatchSettings s_;
  Mark start_;
  RecentMotion recent_;       // the last kRestSteps steps
  std::optional<Mark> late_;   // the first step at or after 3 T / 4
  std::deque<Mark> quarter_;   // the marks of the last T/4 (oldest first)
  double largest_ = 0.0;
  int watched_ = -1;
  double clock_ = 0.0;         // the relaxation clock (MotionMark) at the last step observed
  double last_elapsed_ = 0.0;
};

}  // namespace dda
