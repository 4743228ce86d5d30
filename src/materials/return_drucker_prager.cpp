#include "materials/return_drucker_prager.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "materials/scalar_root.hpp"
#include "materials/yield_drucker_prager.hpp"

namespace dda {

namespace {

const Vec4 kUnit{1.0, 1.0, 1.0, 0.0};  // the identity tensor in Voigt form

// 2G times the deviatoric projector acting on an engineering strain (shear row: G gxy).
Mat4 deviatoric_stiffness(double shear) {
  Mat4 p = Mat4::Zero();
  p.topLeftCorner<3, 3>() = Mat3::Identity() - Mat3::Constant(1.0 / 3.0);
  p(kXY, kXY) = 0.5;
  return 2.0 * shear * p;
}

}  // namespace

PlasticReturn return_drucker_prager(const DruckerPragerParameters& p, const ElasticModuli& moduli,
                                    const Vec4& trial, double eps_p_start) {
  const double g = moduli.shear, k = moduli.bulk;
  const Mat4 elastic = elastic_matrix4(moduli);
  const DruckerPragerCoefficients dp =
      drucker_prager_coefficients(p.match, p.friction_angle, p.dilation_angle);
  const CohesionLaw law(p.hardening, p.cohesion);

  const Vec4 dev = deviator(trial);
  const double q = std::sqrt(j2_invariant(trial));  // sqrt(J2) of the trial
  const double p_trial = mean_stress(trial);
  const double c_start = law.value(eps_p_start);
  // Stress scale as in the Mohr-Coulomb return (return_mohr_coulomb.cpp).
  const double scale = std::max({q, std::abs(p_trial), dp.xi * c_start, 1e-12 * moduli.young});
  const double f_trial = q + dp.eta * p_trial - dp.xi * c_start;
  if (f_trial <= kDecisionTolerance * scale) return elastic_return(trial, eps_p_start, elastic);

  // Newton tolerances: the residuals are stresses, so 1e-14 of the scale (round-off of a
  // few flops); the unknowns are strains, bounded by 1e-15 of their first estimate.
  const double g_tol = 1e-14 * scale;

  // Cone.
  const double stiffness = g + k * dp.eta * dp.eta_bar;
  auto cone = [&](double dgamma, double* d) {
    const double e = eps_p_start + dp.xi * dgamma;
    *d = -(stiffness + dp.xi * dp.xi * law.slope(e));
    return q - g * dgamma + dp.eta * (p_trial - k * dp.eta_bar * dgamma) - dp.xi * law.value(e);
  };
  const double first = f_trial / stiffness;
  const ScalarRoot cone_root = find_root_above(cone, 0.0, first, g_tol, 1e-15 * first);
  // q > 0 only guards the division below (a purely hydrostatic trial goes to the apex).
  if (cone_root.converged && q > 0.0 && q - g * cone_root.x >= -kDecisionTolerance * scale) {
    const double dgamma = cone_root.x;
    const double e = eps_p_start + dp.xi * dgamma;
    const double factor = std::max(0.0, 1.0 - g * dgamma / q);
    PlasticReturn out;
    out.stress = factor * dev + (p_trial - k * dp.eta_bar * dgamma) * kUnit;
    out.eps_p = e;
    out.branch = Branch::Cone;
    // D = 2G (1 - G dgamma / sqrt J2) I_dev + 2G (G dgamma / sqrt J2) n n + K 1 1
    //     - (sqrt2 G n + K eta_bar 1)(sqrt2 G n + K eta 1) / A,   n = s'_trial / |s'_trial|,
    // A = G + K eta eta_bar + xi^2 H (de Souza Neto et al. 2008, eq. 8.78, derived again in
    // tension-positive Voigt form; n acts on engineering strain as n . e).
    const Vec4 n = dev / (std::numbers::sqrt2 * q);
    const double a = stiffness + dp.xi * dp.xi * law.slope(e);
    const Vec4 flow_side = std::numbers::sqrt2 * g * n + k * dp.eta_bar * kUnit;
    const Vec4 yield_side = std::numbers::sqrt2 * g * n + k * dp.eta * kUnit;
    out.tangent = factor * deviatoric_stiffness(g) +
                  2.0 * g * (g * dgamma / q) * n * n.transpose() + k * kUnit * kUnit.transpose() -
                  flow_side * yield_side.transpose() / a;
    return out;
  }

  // Apex.
  if (dp.eta <= 0.0 || dp.eta_bar <= 0.0)
    return failed_return(trial, eps_p_start, elastic,
                         "drucker_prager: the trial stress is beyond the apex and the friction "
                         "or dilation angle is 0, so no return exists",
                         0.0);
  const double ratio = dp.xi / dp.eta_bar;  // d eps_p / d(plastic volume change)
  auto apex = [&](double dv, double* d) {
    const double e = eps_p_start + ratio * dv;
    *d = -(k + dp.xi * ratio * law.slope(e) / dp.eta);
    return p_trial - k * dv - dp.xi * law.value(e) / dp.eta;
  };
  const double apex_start = p_trial - dp.xi * c_start / dp.eta;
  const double first_dv = std::max(apex_start, 0.0) / k;
  const ScalarRoot apex_root =
      find_root_above(apex, 0.0, first_dv > 0.0 ? first_dv : 1e-12, g_tol, 1e-15 * first_dv);
  if (!apex_root.converged || apex_start < -kDecisionTolerance * scale)
    return failed_return(trial, eps_p_start, elastic,
                         "drucker_prager: no return to the cone or the apex (cohesion "
                         "softening too steep?)",
                         0.5);
  const double dv = apex_root.x;
  const double e = eps_p_start + ratio * dv;
  PlasticReturn out;
  out.stress = (p_trial - k * dv) * kUnit;
  out.eps_p = e;
  out.branch = Branch::Apex;
  // dp/d(volume strain) = K h / (K + h), h = xi^2 H / (eta eta_bar): zero when perfectly
  // plastic.
  const double h = dp.xi * ratio * law.slope(e) / dp.eta;
  out.tangent = (k * h / (k + h)) * kUnit * kUnit.transpose();
  return out;
}

}  // namespace dda
