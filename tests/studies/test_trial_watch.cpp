// The trial verdict (studies/trial_watch.hpp) on made-up paths of one watched point: a steady
// failure, a transient that dies away, motions that slow but have not stopped by T/2 (coming
// to rest short of d, or heading beyond it), one that dies just before T/2, a jump
// beyond the failure displacement, a slow creep judged at the end, and a dynamic trial.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <optional>

#include "studies/trial_watch.hpp"

namespace {

using namespace dda;

// A static trial: d = 0.05 m, T = 2 s, steps of 10 ms. The speed limit is that of a mechanism
// at 0.002 g moving a dt / 2 per unit time: 0.002 x 9.81 x 0.01 / 2 = 9.81e-5 m/s.
constexpr double kDt = 0.01;
TrialWatchSettings static_settings() { return {0.05, 2.0, 0.002, 0.0, 9.81}; }
constexpr double kLimit = 0.002 * 9.81 * kDt / 2.0;

struct Outcome {
  TrialStop stop = TrialStop::Continue;
  double time = 0.0;  // when it stopped (or the trial's end)
  SpeedWindow end;
};

// Runs the watch along x(t) until it stops or the trial time is over.
Outcome follow(const TrialWatchSettings& s, const std::function<double(double)>& x) {
  TrialWatch watch(s, {Vec2::Zero()});
  Outcome o;
  long step = 0;
  for (double t = kDt; t <= s.trial_time + 1e-9; t += kDt) {
    ++step;
    o.time = t;
    o.stop = watch.observe({Vec2(x(t), 0.0)}, t, step);
    if (o.stop != TrialStop::Continue) break;
  }
  o.end = watch.end_speed({Vec2(x(o.time), 0.0)}, o.time, step);
  return o;
}

}  // namespace

TEST_CASE("a static trial's speed limit is a dt / 2 of a mechanism at the detect acceleration",
          "[fos][verdict]") {
  const TrialWatch watch(static_settings(), {Vec2::Zero()});
  CHECK(watch.speed_limit(1.0, 100) == Approx(kLimit).epsilon(1e-12));
  // Shorter steps (cuts) lower it in proportion: a dt^2 / 2 a step.
  CHECK(watch.speed_limit(1.0, 200) == Approx(kLimit / 2.0).epsilon(1e-12));
  // A dynamic trial: d / T whatever the steps.
  TrialWatchSettings dynamic = static_settings();
  dynamic.dynamic_coefficient = 1.0;
  CHECK(TrialWatch(dynamic, {Vec2::Zero()}).speed_limit(1.0, 100) == Approx(0.05 / 2.0));
}

TEST_CASE("a failure fast over the last quarter stops at half the trial time, a transient is "
          "let die",
          "[fos][verdict]") {
  SECTION("10 times the limit and slowly speeding up: failing at T/2") {
    const Outcome o = follow(static_settings(), [](double t) { return 10.0 * kLimit * (t + 0.1 * t * t); });
    CHECK(o.stop == TrialStop::MovingFast);
    // The first step at or after T/2, within a step.
    CHECK(o.time == Approx(1.0).margin(1.01 * kDt));
    // Over the last 20 steps (0.8 to 1.0 s): 10 limit (1 + 0.1 x 1.8).
    CHECK(o.end.speed == Approx(11.8 * kLimit).epsilon(1e-9));
  }
  SECTION("a transient from 60 times the limit, dying with a time constant of 0.15 s") {
    // The load-transfer transients of verification/slope-cut: 10 to 60 times the limit for
    // a few tenths of a second. v = 60 limit exp(-t / 0.15): below the limit after 0.61 s
    // (before T/2). At rest once its mean over the last 20 steps (0.2 s) is below 1 % of the
    // limit: 60 tau exp(-t / tau) (exp(0.2 / tau) - 1) / 0.2 = 0.01, t = 1.416 s.
    const double tau = 0.15;
    const Outcome o = follow(static_settings(), [tau](double t) {
      return 60.0 * kLimit * tau * (1.0 - std::exp(-t / tau));
    });
    CHECK(o.stop == TrialStop::AtRest);
    const double rest = -tau * std::log(0.01 * 0.2 / (60.0 * tau * (std::exp(0.2 / tau) - 1.0)));
    CHECK(o.time == Approx(rest).margin(1.01 * kDt));
  }
  SECTION("slowing steadily from 20 times the limit, still fast at T/2: failing there") {
    // v = 20 limit (1 - t / 4): at T/2 the last quarter averages 20 (1 - 0.75 / 4) = 16.25
    // times the limit, the last 20 steps 20 (1 - 0.9 / 4) = 15.5 times, and the last eighth
    // moved 0.925 of the one before: at that pace an e-fold takes 25 / -ln(0.925) = 320
    // steps, longer than the trial's 200: not decaying, failing.
    const Outcome o = follow(static_settings(), [](double t) {
      return 20.0 * kLimit * (t - t * t / 8.0);
    });
    CHECK(o.stop == TrialStop::MovingFast);
    CHECK(o.time == Approx(1.0).margin(1.01 * kDt));
  }
  SECTION("a slow geometric decay is predicted to its end; one heading beyond d fails at T/2") {
    // v = V exp(-t / tau): x(infinity) = V tau, and the series of the eighths is exact.
    // tau = 1 s (T = 2 s, an e-fold in 100 of its 200 steps): each eighth moves exp(-0.25) =
    // 0.78 of the one before, which a rule asking it to halve called failing at T/2 although
    // it stops at 20 limit tau.
    const double tau = 1.0;
    const auto slow = [tau](double V) {
      return [V, tau](double t) { return V * tau * (1.0 - std::exp(-t / tau)); };
    };
    const Outcome resting = follow(static_settings(), slow(20.0 * kLimit));
    CHECK(resting.stop == TrialStop::Continue);  // still above the limit at T, not failing
    CHECK(resting.end.speed > resting.end.limit);
    TrialWatch watch(static_settings(), {Vec2::Zero()});
    long step = 0;
    const auto x = slow(20.0 * kLimit);
    for (double t = kDt; t <= 2.0 + 1e-9; t += kDt) watch.observe({Vec2(x(t), 0.0)}, t, ++step);
    const std::optional<double> heading = watch.predicted_displacement({Vec2(x(2.0), 0.0)}, 2.0, step);
    REQUIRE(heading);
    CHECK(*heading == Approx(20.0 * kLimit * tau).epsilon(1e-6));
    // tau = 1.5 s (an e-fold in 150 steps: decaying), V tau = 0.08 m, beyond d = 0.05 m (at
    // T/2 it has moved 0.039 m, at 260 times the limit): failing as soon as it may be judged,
    // at T/2.
    const double tau_long = 1.5;
    const Outcome running = follow(static_settings(), [tau_long](double t) {
      return 0.08 * (1.0 - std::exp(-t / tau_long));
    });
    CHECK(running.stop == TrialStop::MovingFast);
    CHECK(running.time == Approx(1.0).margin(1.01 * kDt));
  }
  SECTION("fast until 3T/8, then dying within the last eighth before T/2: let come to rest") {
    // The 652-block slope at a tenth of the penalty, F = 0.995: steady for three eighths,
    // then the last eighth before T/2 moved 0.24 of the one before, and the trial came to
    // rest (docs/factor-of-safety.md, section 2). Here v = 20 limit until 0.75 s, then
    // 20 limit exp(-(t - 0.75) / 0.1): at T/2 the last quarter averages 20 (0.25 + 0.0918)
    // / 0.5 = 13.7 times the limit, but its last eighth moved 0.0918 / 0.25 = 0.37 of the
    // one before. At rest once the mean speed over the last 20 steps falls below 1 % of the
    // limit: 20 x 0.1 exp(-(t - 0.95) / 0.1) (1 - exp(-2)) / 0.2 = 0.01, t = 1.626 s.
    const double v = 20.0 * kLimit, t0 = 0.75, tau = 0.1;
    const Outcome o = follow(static_settings(), [=](double t) {
      return t < t0 ? v * t : v * t0 + v * tau * (1.0 - std::exp(-(t - t0) / tau));
    });
    CHECK(o.stop == TrialStop::AtRest);
    const double rest = 0.95 - tau * std::log(0.01 * 0.2 / (20.0 * tau * (1.0 - std::exp(-2.0))));
    CHECK(o.time == Approx(rest).margin(1.01 * kDt));
  }
  SECTION("a jump beyond the failure displacement") {
    const Outcome o = follow(static_settings(), [](double t) { return t < 0.3 ? 0.0 : 0.06; });
    CHECK(o.stop == TrialStop::MovedTooFar);
    CHECK(o.time == Approx(0.3).margin(1.01 * kDt));
  }
  SECTION("twice the limit throughout: runs its time, and its end speed says failing") {
    const Outcome o = follow(static_settings(), [](double t) { return 2.0 * kLimit * t; });
    CHECK(o.stop == TrialStop::Continue);
    CHECK(o.time == Approx(2.0).margin(1e-9));
    // Over the last quarter.
    CHECK(o.end.speed == Approx(2.0 * kLimit).epsilon(1e-9));
    CHECK(o.end.limit == Approx(kLimit).epsilon(1e-9));
    // Not decaying: heading for infinity.
    TrialWatch watch(static_settings(), {Vec2::Zero()});
    long step = 0;
    for (double t = kDt; t <= 2.0 + 1e-9; t += kDt) watch.observe({Vec2(2.0 * kLimit * t, 0.0)}, t, ++step);
    const std::optional<double> heading = watch.predicted_displacement({Vec2(4.0 * kLimit, 0.0)}, 2.0, step);
    REQUIRE(heading);
    CHECK(std::isinf(*heading));
  }
}

TEST_CASE("a dynamic trial is never stopped for speed, only at rest or beyond d",
          "[fos][verdict]") {
  TrialWatchSettings dynamic = static_settings();
  dynamic.dynamic_coefficient = 1.0;
  // 0.02 m/s against the creep speed d / T = 0.025 m/s: runs its time, then judged on its end
  // speed (below the limit: stable).
  const Outcome o = follow(dynamic, [](double t) { return 0.02 * t; });
  CHECK(o.stop == TrialStop::Continue);
  CHECK(o.end.speed == Approx(0.02).epsilon(1e-9));
  CHECK(o.end.limit == Approx(0.025));
}

TEST_CASE("the decay horizon is counted on the relaxation clock: shorter steps do not shorten "
          "it",
          "[fos][verdict]") {
  // A horizon of 50 steps of 0.01 s: 50 x 1e-4 = 5e-3 s^2 on the clock (sum of dt^2). The
  // motion x = V tau (1 - exp(-t / tau)), tau = 0.4 s, loses 1/e in 40 steps of 0.01 s
  // (4e-3 s^2: decaying) or in 80 steps of 0.005 s (80 x 2.5e-5 = 2e-3 s^2: decaying too,
  // where a count of plain steps, 80 > 50, would call it not decaying). At 0.02 s, 20
  // steps of 4e-4 s^2 = 8e-3 s^2: beyond the horizon, and still at 8 times the speed limit
  // at T/2, so failing there.
  TrialWatchSettings s = static_settings();
  s.decay_horizon_steps = 50.0;
  s.reference_dt = 0.01;
  const double tau = 0.4, V = 0.02;
  const auto heading = [&](double dt) {
    TrialWatch watch(s, {Vec2::Zero()});
    const auto x = [&](double t) { return V * tau * (1.0 - std::exp(-t / tau)); };
    long step = 0;
    double t = 0.0;
    const long steps = std::lround(s.trial_time / dt);
    for (long k = 1; k <= steps; ++k) {
      t = static_cast<double>(k) * dt;
      // A stopped watch is not fed further: it is read at the step it stopped.
      if (watch.observe({Vec2(x(t), 0.0)}, t, ++step) != TrialStop::Continue) break;
    }
    return watch.predicted_displacement({Vec2(x(t), 0.0)}, t, step);
  };
  for (const double dt : {0.01, 0.005}) {
    const std::optional<double> h = heading(dt);
    REQUIRE(h);
    // Decaying: the series of the exponential's eighths is exact, V tau.
    CHECK(*h == Approx(V * tau).epsilon(1e-6));
  }
  const std::optional<double> coarse = heading(0.02);
  REQUIRE(coarse);
  CHECK(std::isinf(*coarse));
}
