#include "studies/trial_watch.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

namespace dda {
namespace {

// The at-rest test: over a window of this many steps, every watched point moved at less than
// this share of the speed limit.
constexpr int kRestSteps = 20;
constexpr double kRestSpeedShare = 0.01;
// A damped trial fails early on motion at more than this multiple of the speed limit.
constexpr double kFailSpeedShare = 4.0;
// ... unless it is dying: its fastest point moved less than this share of the distance over
// the last eighth of the trial time that it moved over the eighth before. A motion that
// halves in an eighth moves at most as far again if it goes on dying so. Measured on the
// 652-block slope of verification/slope-cut at a tenth of the auto penalty (T = 2.07 s): at
// F = 0.995 the eighths up to T/2 moved 0.43, 0.44, 0.31 and 0.076 mm (0.24 of the one
// before), and run to 3 T the trial came to rest at 1.56 s, where T/2 had called it failing;
// failing trials at F = 1.0 and 1.02 showed 1.2 and 0.83 and kept moving.
constexpr double kDyingShare = 0.5;

// The farthest any watched point moved from `from` to `to` (m).
double farthest(const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
  double d = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i) d = std::max(d, (to[i] - from[i]).norm());
  return d;
}

}  // namespace

TrialWatch::TrialWatch(const TrialWatchSettings& settings, std::vector<Vec2> start)
    : s_(settings), start_{std::move(start), 0.0, 0}, ring_(kRestSteps), quarter_{start_} {
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
  return SpeedWindow{span > 0.0 ? farthest(from.points, to) / span : 0.0,
                     speed_limit(span, step - from.step)};
}

bool TrialWatch::dying(const std::vector<Vec2>& now, double elapsed) const {
  const double eighth = 0.125 * s_.trial_time;
  // The first mark of the last eighth (the marks are in time order).
  const auto mid = std::lower_bound(quarter_.begin(), quarter_.end(), elapsed - eighth,
                                    [](const Mark& m, double t) { return m.time < t; });
  if (mid == quarter_.end() || mid == quarter_.begin()) return false;
  return farthest(mid->points, now) < kDyingShare * farthest(quarter_.front().points, mid->points);
}

TrialStop TrialWatch::observe(const std::vector<Vec2>& now, double elapsed, long steps) {
  assert(now.size() == start_.points.size());
  const double T = s_.trial_time;
  for (std::size_t i = 0; i < now.size(); ++i) {
    const double u = (now[i] - start_.points[i]).norm();
    if (u > largest_) {
      largest_ = u;
      watched_ = static_cast<int>(i);
    }
  }
  if (largest_ > s_.failure_displacement) return TrialStop::MovedTooFar;
  if (!late_ && elapsed >= 0.75 * T) late_ = Mark{now, elapsed, steps};
  // At rest: after a quarter of the trial time, every watched point moved over the last
  // kRestSteps steps at less than 1 % of the speed limit; the rest would repeat the state.
  const std::size_t slot = static_cast<std::size_t>(steps % kRestSteps);
  std::optional<SpeedWindow> recent;
  if (steps > kRestSteps) recent = since(ring_[slot], now, elapsed, steps);
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
    // And not dying over the last eighth (kDyingShare): such a transient is let run, and
    // judged again at every step.
    if (recent && recent->speed > recent->limit && elapsed >= 0.5 * T) {
      const SpeedWindow last_quarter = since(quarter_.front(), now, elapsed, steps);
      if (last_quarter.speed > kFailSpeedShare * last_quarter.limit && !dying(now, elapsed)) {
        stop = TrialStop::MovingFast;
      }
    }
    // A stopped trial keeps the marks before this step: its end speed is taken over the
    // last kRestSteps steps (end_speed).
    if (stop != TrialStop::Continue) return stop;
    quarter_.push_back(Mark{now, elapsed, steps});
  }
  ring_[slot] = Mark{now, elapsed, steps};
  return TrialStop::Continue;
}

SpeedWindow TrialWatch::end_speed(const std::vector<Vec2>& end, double elapsed, long steps) const {
  const Mark* from = nullptr;
  if (late_ && elapsed > late_->time) {
    from = &*late_;
  } else if (steps > kRestSteps) {
    // The mark kRestSteps steps back, or kRestSteps - 1 when this step's own mark was kept.
    from = &ring_[static_cast<std::size_t>(steps % kRestSteps)];
    if (from->step == steps) from = &ring_[static_cast<std::size_t>((steps + 1) % kRestSteps)];
  } else if (elapsed > 0.0) {
    from = &start_;
  }
  return from != nullptr ? since(*from, end, elapsed, steps) : SpeedWindow{};
}

}  // namespace dda
