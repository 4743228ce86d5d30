#include "materials/yield_drucker_prager.hpp"

#include <cmath>
#include <numbers>

namespace dda {

namespace {

// (eta-like, xi-like) of one angle for a match.
std::pair<double, double> match_pair(DruckerPragerMatch match, double angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  const double s = std::sin(a), c = std::cos(a);
  switch (match) {
    case DruckerPragerMatch::Outer: {
      const double d = std::numbers::sqrt3 * (3.0 - s);
      return {6.0 * s / d, 6.0 * c / d};
    }
    case DruckerPragerMatch::Inner: {
      const double d = std::numbers::sqrt3 * (3.0 + s);
      return {6.0 * s / d, 6.0 * c / d};
    }
    case DruckerPragerMatch::PlaneStrain:
      break;
  }
  const double t = std::tan(a);
  const double d = std::sqrt(9.0 + 12.0 * t * t);
  return {3.0 * t / d, 3.0 / d};
}

}  // namespace

DruckerPragerCoefficients drucker_prager_coefficients(DruckerPragerMatch match, double friction_deg,
                                                      double dilation_deg) {
  DruckerPragerCoefficients k;
  const auto [eta, xi] = match_pair(match, friction_deg);
  k.eta = eta;
  k.xi = xi;
  k.eta_bar = match_pair(match, dilation_deg).first;
  return k;
}

double drucker_prager_yield(const Vec4& s, double cohesion, const DruckerPragerCoefficients& k) {
  return std::sqrt(j2_invariant(s)) + k.eta * mean_stress(s) - k.xi * cohesion;
}

Vec4 drucker_prager_flow(const Vec4& s, const DruckerPragerCoefficients& k) {
  const Vec4 d = deviator(s);
  const double q = 2.0 * std::sqrt(j2_invariant(s));
  return {d[kXX] / q + k.eta_bar / 3.0, d[kYY] / q + k.eta_bar / 3.0, d[kZZ] / q + k.eta_bar / 3.0,
          2.0 * d[kXY] / q};
}

}  // namespace dda
