#include "studies/trial_watch.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

namespace dda {
namespace {

// The at-rest test: over a window of this many steps, every watched point moved at less than
// this share of the speed limit.
constexpr int kRestSteps = 20;
constexpr double kRestSpeedShare = 0.01;
// A damped trial fails early on motion at more than this multiple of the speed limit.
constexpr double kFailSpeedShare = 4.0;
// ... and only when its decay would carry it beyond the failure displacement
// (predicted_displacement). A static trial relaxes towards its equilibrium by a steady share
// a step, so its motion decays geometrically once the load has passed on, and the rest of it
// is the geometric series of the last eighths. Measured on the 3-cell vertical cut of
// verification/vertical-cut (Mohr-Coulomb blocks, reduced strengths, dt 0.01 s, trials of
// 27 s): the motion per 100 steps fell by 0.53, 0.62, 0.76 and 0.86 at F = 1.30, 1.34, 1.38
// and 1.42, and each came to rest after 4.1, 5.7, 8.1 and 13 mm (the last still creeping at
// 27 s, 0.35 of the speed limit), where a rule that asked the last eighth to halve called
// every one of them above 1.33 failing at T/2 of a 9 s trial, and the factor rose with T.
// From F = 1.46 the ratio stays at 0.95 to 0.99, an e-fold in 2000 steps or more against
// the 54 steps of the consolidation's relaxation: the motion runs on towards d. A motion
// decaying more slowly than TrialWatchSettings::decay_horizon_steps is therefore not
// decaying: a geometric rest extrapolated from a ratio near 1 is long and unreliable. The
// horizon is counted on the relaxation clock (sum of dt^2), so that steps cut shorter, each
// relaxing a mode by a share that goes as dt^2, do not shorten it.

}  // namespace

TrialWatch::TrialWatch(const TrialWatchSettings& settings, std::vector<Vec2> start)
    : s_(settings), start_{std::move(start), 0.0, 0}, recent_(kRestSteps, start_), quarter_{start_} {
  assert(s_.failure_displacement > 0.0 && s_.trial_time > 0.0);
}

double TrialWatch::speed_limit(double window_time, long window_steps) const {
  const double k = s_.dynamic_coefficient;
  if (k >= 1.0 || window_steps <= 0) return s_.failure_displacement / s_.trial_time;
  // Per step v' = k v + a dt: a damped mechanism settles to v = a dt / (1 - k), and moves
  // a dt (1 + k) / (2 (1 - k)) per unit time over the step (a dt / 2 from rest, k = 0).
  const double mean_dt = window_time / static_cast<double>(window_steps);
  return s_.detect_acceleration * s_.gravity * mean_dt * (1.0 + k) / (2.0 * (1.0 - k));
}

SpeedWindow TrialWatch::since(const Mark& from, const std::vector<Vec2>& to, double time,
                              long step) const {
  const double span = time - from.time;
  return SpeedWindow{span > 0.0 ? farthest_motion(from.points, to) / span : 0.0,
                     speed_limit(span, step - from.step)};
}

std::optional<double> TrialWatch::predicted_displacement(const std::vector<Vec2>& now,
                                                         double elapsed, long steps) const {
  if (s_.dynamic_coefficient >= 1.0 || quarter_.empty()) return std::nullopt;
  const double eighth = 0.125 * s_.trial_time;
  if (quarter_.front().time > elapsed - 2.0 * eighth + 1e-12 * s_.trial_time) return std::nullopt;
  // The first mark of the last eighth (the marks are in time order).
  const auto mid = std::lower_bound(quarter_.begin(), quarter_.end(), elapsed - eighth,
                                    [](const Mark& m, double t) { return m.time < t; });
  if (mid == quarter_.end() || mid == quarter_.begin()) return std::nullopt;
  // Each eighth's speed as a multiple of its own speed limit, which follows its mean step:
  // a steady mechanism moves a dt^2 / 2 a step, so a window of shorter steps (a cut, the
  // step landing on T) is slower in m/s without the motion decaying.
  const SpeedWindow before = since(quarter_.front(), mid->points, mid->time, mid->step);
  const SpeedWindow last = since(*mid, now, elapsed, steps);
  if (before.speed <= 0.0 || before.limit <= 0.0 || last.limit <= 0.0) return std::nullopt;
  if (last.speed <= 0.0) return largest_;
  const double rho = (last.speed / last.limit) / (before.speed / before.limit);
  // Decaying: an e-fold within the horizon, both on the relaxation clock (s^2): the horizon
  // is decay_horizon_steps steps of reference_dt, or T in steps of the window's mean length.
  const double window_clock = clock_ - mid->relaxation_clock;
  const double mean_dt = (elapsed - mid->time) / static_cast<double>(steps - mid->step);
  const double horizon = s_.decay_horizon_steps > 0.0 && s_.reference_dt > 0.0
                             ? s_.decay_horizon_steps * s_.reference_dt * s_.reference_dt
                             : s_.trial_time * mean_dt;
  if (rho >= 1.0 || -window_clock / std::log(rho) > horizon) {
    return std::numeric_limits<double>::infinity();
  }
  // The geometric rest after the last eighth's motion.
  return largest_ + last.speed * (elapsed - mid->time) * rho / (1.0 - rho);
}

TrialStop TrialWatch::observe(const std::vector<Vec2>& now, double elapsed, long steps) {
  assert(now.size() == start_.points.size());
  clock_ += (elapsed - last_elapsed_) * (elapsed - last_elapsed_);
  last_elapsed_ = elapsed;
  const double T = s_.trial_time;
  for (std::size_t i = 0; i < now.size(); ++i) {
    const double u = (now[i] - start_.points[i]).norm();
    if (u > largest_) {
      largest_ = u;
      watched_ = static_cast<int>(i);
    }
  }
  if (largest_ > s_.failure_displacement) return TrialStop::MovedTooFar;
  if (!late_ && elapsed >= 0.75 * T) late_ = Mark{now, elapsed, steps, clock_};
  // At rest: after a quarter of the trial time, every watched point moved over the last
  // kRestSteps steps at less than 1 % of the speed limit; the rest would repeat the state.
  std::optional<SpeedWindow> recent;
  if (steps > kRestSteps) recent = since(recent_.window_start(steps), now, elapsed, steps);
  if (recent && elapsed >= 0.25 * T && recent->speed < kRestSpeedShare * recent->limit) {
    return TrialStop::AtRest;
  }
  TrialStop stop = TrialStop::Continue;
  if (s_.dynamic_coefficient < 1.0) {
    // A damped trial has no inertia to carry it through a pause, so a mechanism shows itself
    // as a steady speed: a static step moves it a dt^2 / 2 from rest, whatever came before.
    // When the reduced strengths first act, though, load passes from the contacts that slip
    // to their neighbours, and a soft penalty lets a group move a millimetre at 10 to 60
    // times the limit for a few tenths of a second before it comes to rest
    // (verification/slope-cut, 652 blocks, penalty auto / 10: 0.58 mm over 0.8 s at
    // F = 0.92, then at rest; a window of the last 20 steps after T/4 called it failing and
    // gave F = 0.910). Two eighths of the last quarter, the later not slower, do not tell
    // such transients apart either: on the toppling slopes of verification/slope-cut they
    // called 11 trials failing that came to rest (docs/factor-of-safety.md, section 2).
    while (quarter_.size() > 1 && quarter_[1].time <= elapsed - 0.25 * T) quarter_.pop_front();
    // Moving fast: after half the trial time, over the whole last quarter at more than 4
    // times the limit, and still faster than the limit over the last 20 steps. The quarter
    // alone called a transient failing that had died down at T/2 (the steep slope of
    // verification/slope-cut at dt 0.002, F = 0.578: 2e-6 m/s over the last 20 steps against
    // a limit of 2e-5).
    // And not decaying so that it comes to rest short of the failure displacement
    // (predicted_displacement): such a motion is let run, and judged again at every step.
    if (recent && recent->speed > recent->limit && elapsed >= 0.5 * T) {
      const SpeedWindow last_quarter = since(quarter_.front(), now, elapsed, steps);
      if (last_quarter.speed > kFailSpeedShare * last_quarter.limit) {
        const std::optional<double> heading = predicted_displacement(now, elapsed, steps);
        if (!heading || *heading > s_.failure_displacement) stop = TrialStop::MovingFast;
      }
    }
    // A stopped trial keeps the marks before this step: its end speed is taken over the
    // last kRestSteps steps (end_speed).
    if (stop != TrialStop::Continue) return stop;
    quarter_.push_back(Mark{now, elapsed, steps, clock_});
  }
  recent_.record(Mark{now, elapsed, steps, clock_});
  return TrialStop::Continue;
}

SpeedWindow TrialWatch::end_speed(const std::vector<Vec2>& end, double elapsed, long steps) const {
  const Mark* from = nullptr;
  if (late_ && elapsed > late_->time) {
    from = &*late_;
  } else if (steps > kRestSteps) {
    // The mark kRestSteps steps back, or kRestSteps - 1 when this step's own mark was kept.
    from = &recent_.window_start(steps);
  } else if (elapsed > 0.0) {
    from = &start_;
  }
  return from != nullptr ? since(*from, end, elapsed, steps) : SpeedWindow{};
}

}  // namespace dda
