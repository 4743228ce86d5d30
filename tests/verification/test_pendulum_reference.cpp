// The CVODE reference solution of the rigid pendulum against closed forms: the linear period,
// the exact period 4 K(sin(theta0/2)) / omega0 with K computed independently by the
// arithmetic-geometric mean, the over-the-top period, energy conservation and the amplitude.
//
// Tolerance budget: CVODE is run at its default rtol 1e-13 with absolute tolerances scaled to
// the motion; that bounds the LOCAL error per step, and the global error of an oscillator grows
// roughly linearly with the number of periods (a phase error). Measured: period errors below
// 1e-11 relative up to 170 degrees, energy and amplitude errors about 1e-10 over 20 periods at
// 170 degrees. 1e-9 relative is therefore safe by an order of magnitude or more and still far
// tighter than any DDA error the reference will be compared with.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "kinematics/polygon.hpp"
#include "pendulum_reference.hpp"

using namespace dda;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kPi = std::numbers::pi;

// Complete elliptic integral of the first kind, K(k) = int_0^{pi/2} dphi / sqrt(1 - k^2 sin^2),
// by the arithmetic-geometric mean: K(k) = pi / (2 AGM(1, sqrt(1 - k^2))). AGM converges
// quadratically; the loop stops when a and b agree to round-off.
double elliptic_k(double k) {
  double a = 1.0;
  double b = std::sqrt((1.0 - k) * (1.0 + k));
  for (int i = 0; i < 64 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double next_a = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next_a;
  }
  return kPi / (2.0 * a);
}

// Exact period of a swing from rest at theta0 (|theta0| < pi).
double exact_period_from_rest(double theta0, double omega0) {
  return 4.0 * elliptic_k(std::sin(0.5 * std::abs(theta0))) / omega0;
}

// omega0 = 2.3 rad/s, an arbitrary non-round value so that no factor of 1 hides an error.
constexpr double kOmega0Sq = 2.3 * 2.3;

}  // namespace

TEST_CASE("pendulum reference: K by AGM against known values", "[pendulum_reference]") {
  // K(0) = pi/2 exactly; K(1/sqrt 2) = Gamma(1/4)^2 / (4 sqrt(pi)) = 1.854074677301372 (16
  // digits, tabulated). The AGM is exact up to round-off: 1e-14 relative.
  CHECK_THAT(elliptic_k(0.0), WithinRel(kPi / 2.0, 1e-14));
  const double gamma_quarter = std::tgamma(0.25);
  CHECK_THAT(elliptic_k(1.0 / std::sqrt(2.0)),
             WithinRel(gamma_quarter * gamma_quarter / (4.0 * std::sqrt(kPi)), 1e-14));
  CHECK_THAT(elliptic_k(1.0 / std::sqrt(2.0)), WithinRel(1.854074677301372, 1e-14));
}

TEST_CASE("pendulum reference: small-amplitude period is 2 pi / omega0", "[pendulum_reference]") {
  const PendulumParams p{kOmega0Sq, 1e-4, 0.0};
  const double omega0 = std::sqrt(kOmega0Sq);
  const double period = pendulum_period(p);
  // The exact period exceeds 2 pi / omega0 by the factor 1 + theta0^2/16 + ... = 1 + 6.25e-10;
  // with the integration error (measured 4e-13) that stays well below 1e-8 relative. The exact
  // elliptic period is checked as well, to the 1e-9 integration budget.
  CHECK_THAT(period, WithinRel(2.0 * kPi / omega0, 1e-8));
  CHECK_THAT(period, WithinRel(exact_period_from_rest(1e-4, omega0), 1e-9));
}

TEST_CASE("pendulum reference: large-amplitude period is 4 K(sin(theta0/2)) / omega0",
          "[pendulum_reference]") {
  const double omega0 = std::sqrt(kOmega0Sq);
  for (const double deg : {30.0, 90.0, 135.0, 170.0, -120.0}) {
    CAPTURE(deg);
    const double theta0 = deg * kPi / 180.0;
    const double period = pendulum_period({kOmega0Sq, theta0, 0.0});
    // Two crossings, i.e. 1.5 periods of integration: 1e-9 relative (see the budget above).
    CHECK_THAT(period, WithinRel(exact_period_from_rest(theta0, omega0), 1e-9));
  }
  // 170 degrees: the period is 2.44 times the linear one, far outside the linear model.
  CHECK(pendulum_period({kOmega0Sq, 170.0 * kPi / 180.0, 0.0}) > 2.4 * 2.0 * kPi / omega0);
}

TEST_CASE("pendulum reference: period does not depend on where the swing starts",
          "[pendulum_reference]") {
  // Start at the bottom with the speed of a 90-degree swing: omega^2/2 = omega0^2 (1 - cos 90).
  // Same orbit, so the same period 4 K(sin 45 deg) / omega0, to 1e-9 relative.
  const double omega0 = std::sqrt(kOmega0Sq);
  const PendulumParams p{kOmega0Sq, 0.0, -omega0 * std::sqrt(2.0)};
  CHECK_THAT(pendulum_period(p), WithinRel(exact_period_from_rest(kPi / 2.0, omega0), 1e-9));
  // And that swing reaches 90 degrees on both sides (turning points by energy): 1e-9.
  CHECK_THAT(pendulum_amplitude(p, 10.0), WithinRel(kPi / 2.0, 1e-9));
}

TEST_CASE("pendulum reference: over-the-top period", "[pendulum_reference]") {
  // With e = omega^2/2 + omega0^2 (1 - cos theta) > 2 omega0^2 and k^2 = e / (2 omega0^2) > 1,
  // one revolution takes int_0^{2 pi} dtheta / omega = 2 K(1/k) / (k omega0).
  const double omega0 = std::sqrt(kOmega0Sq);
  const double omega_init = 2.5 * omega0;  // e = 3.125 omega0^2, k = 1.25
  const double k = omega_init / (2.0 * omega0);
  const double expected = 2.0 * elliptic_k(1.0 / k) / (k * omega0);
  // One revolution of integration: 1e-9 relative.
  CHECK_THAT(pendulum_period({kOmega0Sq, 0.0, omega_init}), WithinRel(expected, 1e-9));
  CHECK_THAT(pendulum_period({kOmega0Sq, 0.0, -omega_init}), WithinRel(expected, 1e-9));
}

TEST_CASE("pendulum reference: energy is conserved along the trajectory", "[pendulum_reference]") {
  for (const double deg : {1.0, 90.0, 170.0}) {
    CAPTURE(deg);
    const double theta0 = deg * kPi / 180.0;
    const PendulumParams p{kOmega0Sq, theta0, 0.0};
    std::vector<double> times;
    for (int i = 0; i <= 2000; ++i) times.push_back(0.01 * i);  // 20 s: about 7 linear periods
    const PendulumSamples s = pendulum_sample(p, times);
    REQUIRE(s.theta.size() == times.size());
    REQUIRE(s.omega.size() == times.size());
    // e = omega^2/2 - omega0^2 cos(theta), constant. Its scale is the energy of the swing,
    // omega0^2 (1 - cos theta0); relative to that the integration error is ~1e-11, so 1e-9.
    const double e0 = -kOmega0Sq * std::cos(theta0);
    const double scale = kOmega0Sq * (1.0 - std::cos(theta0));
    double worst = 0.0;
    for (std::size_t i = 0; i < times.size(); ++i) {
      const double e = 0.5 * s.omega[i] * s.omega[i] - kOmega0Sq * std::cos(s.theta[i]);
      worst = std::max(worst, std::abs(e - e0) / scale);
    }
    CHECK(worst < 1e-9);
  }
}

TEST_CASE("pendulum reference: samples at the exact period and half period",
          "[pendulum_reference]") {
  // From rest at theta0 > 0 the pendulum swings clockwise first (omega < 0, the code's
  // counter-clockwise-positive convention), is at -theta0 after half a period and back at
  // theta0 after a full one. 1e-9 relative to theta0 for the angles; omega at the turning
  // points is 0 to 1e-9 times the largest speed omega0 sqrt(2 (1 - cos theta0)).
  const double omega0 = std::sqrt(kOmega0Sq);
  const double theta0 = 2.0;  // rad, about 115 degrees
  const double period = exact_period_from_rest(theta0, omega0);
  const double omega_max = omega0 * std::sqrt(2.0 * (1.0 - std::cos(theta0)));
  const PendulumSamples s =
      pendulum_sample({kOmega0Sq, theta0, 0.0}, {0.0, 1e-3, 0.5 * period, period, period, 5.0 * period});
  CHECK(s.theta[0] == theta0);
  CHECK(s.omega[0] == 0.0);
  // theta(t) = theta0 - omega0^2 sin(theta0) t^2 / 2 + O(t^4): O(t^4) ~ 1e-12 here.
  CHECK_THAT(s.theta[1], WithinAbs(theta0 - 0.5 * kOmega0Sq * std::sin(theta0) * 1e-6, 1e-11));
  CHECK(s.omega[1] < 0.0);
  CHECK_THAT(s.theta[2], WithinRel(-theta0, 1e-9));
  CHECK_THAT(s.omega[2], WithinAbs(0.0, 1e-9 * omega_max));
  CHECK_THAT(s.theta[3], WithinRel(theta0, 1e-9));
  CHECK_THAT(s.omega[3], WithinAbs(0.0, 1e-9 * omega_max));
  CHECK(s.theta[4] == s.theta[3]);  // a repeated time gives the same sample
  CHECK_THAT(s.theta[5], WithinRel(theta0, 1e-9));
  CHECK_THAT(s.omega[5], WithinAbs(0.0, 1e-9 * omega_max));
}

TEST_CASE("pendulum reference: amplitude from rest equals theta0", "[pendulum_reference]") {
  const double omega0 = std::sqrt(kOmega0Sq);
  for (const double theta0 : {1e-4, 0.5, -1.5, 2.9}) {
    CAPTURE(theta0);
    const PendulumParams p{kOmega0Sq, theta0, 0.0};
    const double period = exact_period_from_rest(theta0, omega0);
    // |theta| never exceeds theta0 (energy), and the turning points sit at -theta0, theta0, ...
    // alternately, at multiples of half the exact period: all to 1e-9 relative.
    CHECK_THAT(pendulum_amplitude(p, 10.0 * period), WithinRel(std::abs(theta0), 1e-9));
    const auto turns = pendulum_turning_points(p, 10.25 * period);
    REQUIRE(turns.size() == 20);
    for (std::size_t i = 0; i < turns.size(); ++i) {
      CAPTURE(i);
      const double sign = (i % 2 == 0) ? -1.0 : 1.0;
      CHECK_THAT(turns[i].theta, WithinRel(sign * theta0, 1e-9));
      CHECK_THAT(turns[i].time, WithinRel(0.5 * period * static_cast<double>(i + 1), 1e-9));
    }
  }
  // Not a turning point at the end: the amplitude over a quarter swing is theta0 (at t = 0).
  CHECK(pendulum_amplitude({kOmega0Sq, 1.0, 0.0}, 0.1) == 1.0);
}

TEST_CASE("pendulum reference: parameters and the regular n-gon inertia", "[pendulum_reference]") {
  // Square of side a: R = a / sqrt 2, I_c / m = a^2 / 6. Round-off only: 1e-14.
  CHECK_THAT(ngon_centroidal_inertia_per_mass(4, 1.0 / std::sqrt(2.0)), WithinRel(1.0 / 6.0, 1e-14));
  // Octagon of circumradius 5 (the paper's swinging octagon) against exact polygon integration
  // of the code's own geometry: I_c / m = (sxx + syy) / area. Round-off only: 1e-13.
  Polygon octagon;
  for (int i = 0; i < 8; ++i) {
    const double a = 2.0 * kPi * i / 8.0;
    octagon.push_back(Vec2(5.0 * std::cos(a), 5.0 * std::sin(a)));
  }
  const Moments m = polygon_moments(octagon);
  CHECK_THAT(ngon_centroidal_inertia_per_mass(8, 5.0), WithinRel((m.sxx + m.syy) / m.area, 1e-13));
  // Many sides tend to the disc, R^2 / 2.
  CHECK_THAT(ngon_centroidal_inertia_per_mass(100000, 2.0), WithinRel(2.0, 1e-9));

  // omega0^2 = m g l / I_p with I_p = I_c + m l^2 (the pendulum of the swinging octagon, pinned
  // 4.5 m from its centre): arithmetic only, 1e-14.
  const double mass = 2700.0 * m.area, g = 9.81, l = 4.5;
  const double ip = mass * (ngon_centroidal_inertia_per_mass(8, 5.0) + l * l);
  const PendulumParams p = pendulum_params(mass, g, l, ip, 0.2, -0.1);
  CHECK_THAT(p.omega0_sq, WithinRel(g * l / (ngon_centroidal_inertia_per_mass(8, 5.0) + l * l), 1e-14));
  CHECK(p.theta0 == 0.2);
  CHECK(p.omega_init == -0.1);
  CHECK_THROWS_AS(pendulum_params(mass, g, l, 0.5 * mass * l * l, 0.0, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(ngon_centroidal_inertia_per_mass(2, 1.0), std::invalid_argument);
}

TEST_CASE("pendulum reference: bad input and CVODE failures are reported", "[pendulum_reference]") {
  CHECK_THROWS_AS(pendulum_period({0.0, 1.0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(pendulum_period({1.0, 0.0, 0.0}), std::invalid_argument);  // no motion
  CHECK_THROWS_AS(pendulum_period({1.0, kPi, 0.0}), std::invalid_argument);  // separatrix
  CHECK_THROWS_AS(pendulum_sample({1.0, 1.0, 0.0}, {1.0, 0.5}), std::invalid_argument);
  CHECK_THROWS_AS(pendulum_amplitude({1.0, 1.0, 0.0}, -1.0), std::invalid_argument);
  // A CVODE error (flag < 0) is thrown with the flag's name: too few steps allowed.
  PendulumSolverOptions opt;
  opt.max_steps = 5;
  CHECK_THROWS_WITH(pendulum_sample({1.0, 1.0, 0.0}, {100.0}, opt),
                    Catch::Matchers::Contains("CV_TOO_MUCH_WORK"));
  // At rest at the bottom: nothing moves, amplitude 0, no turning points, samples all 0.
  CHECK(pendulum_amplitude({1.0, 0.0, 0.0}, 5.0) == 0.0);
  CHECK(pendulum_turning_points({1.0, 0.0, 0.0}, 5.0).empty());
  const PendulumSamples rest = pendulum_sample({1.0, 0.0, 0.0}, {1.0, 2.0});
  CHECK(rest.theta[1] == 0.0);
  CHECK(rest.omega[1] == 0.0);
}
