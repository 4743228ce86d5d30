// The verdict of a strength-reduction trial, read from where its watched points go step by
// step (docs/factor-of-safety.md, section 2). Positions and times in, verdict out: run_trial
// feeds it from the run loop's observer, and tests feed it made-up paths.
#pragma once

#include <deque>
#include <optional>
#include <vector>

#include "kinematics/types.hpp"

namespace dda {

struct TrialWatchSettings {
  double failure_displacement = 0.0;  // m: a watched point moving farther fails the trial
  double trial_time = 0.0;            // s: T
  double detect_acceleration = 0.002; // share of |g| of the slowest mechanism resolved
  double dynamic_coefficient = 0.0;   // k: 0 static, 1 dynamic
  double gravity = 9.81;              // |g| (m/s^2)
};

// Why a trial stops before its time (Continue: it goes on).
enum class TrialStop {
  Continue,
  MovedTooFar,      // a watched point moved beyond the failure displacement
  AtRest,           // after T/4, every watched point still over the last 20 steps
  MovingFast,       // k < 1, after T/2: fast over the last quarter and the last 20 steps, not dying
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

  double largest_displacement() const { return largest_; }
  int watched_point() const { return watched_; }  // the point that moved most, -1 before any

 private:
  struct Mark {
    std::vector<Vec2> points;
    double time = 0.0;
    long step = 0;
  };
  SpeedWindow since(const Mark& from, const std::vector<Vec2>& to, double time, long step) const;
  // Over the last quarter's marks: the fastest point moved less over the last eighth of the
  // trial time than kDyingShare of what it moved over the eighth before.
  bool dying(const std::vector<Vec2>& now, double elapsed) const;

  TrialWatchSettings s_;
  Mark start_;
  std::vector<Mark> ring_;     // the last kRestSteps steps
  std::optional<Mark> late_;   // the first step at or after 3 T / 4
  std::deque<Mark> quarter_;   // the marks of the last T/4 (oldest first)
  double largest_ = 0.0;
  int watched_ = -1;
};

}  // namespace dda
