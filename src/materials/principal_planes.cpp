#include "materials/principal_planes.hpp"

#include <algorithm>
#include <cmath>

#include "materials/scalar_root.hpp"

namespace dda {

namespace {

using PlaneMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxActivePlanes, kMaxActivePlanes>;
using PlanesBy3 = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxActivePlanes, 3>;
using ThreeByPlanes = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxActivePlanes>;

// A pivot below this fraction of the largest one marks the active set's system singular
// (e.g. the Mohr-Coulomb apex with zero dilation: the three flows are all deviatoric).
constexpr double kSingularPivot = 1e-12;

}  // namespace

PlanesReturn return_to_planes(std::span<const PrincipalPlane> planes, const Vec3& trial,
                              const Mat3& elastic, double eps_p_start, const CohesionLaw& law) {
  PlanesReturn out;
  const int m = static_cast<int>(planes.size());
  PlanesBy3 a(m, 3);
  ThreeByPlanes b(3, m);
  PlaneMultipliers r_c(m), r_0(m), h(m);
  for (int k = 0; k < m; ++k) {
    a.row(k) = planes[k].normal.transpose();
    b.col(k) = planes[k].flow;
    r_c[k] = planes[k].cohesion_factor;
    r_0[k] = planes[k].constant;
    h[k] = planes[k].hardening_weight;
  }
  const ThreeByPlanes de_b = elastic * b;
  const PlaneMatrix m0 = a * de_b;
  Eigen::FullPivLU<PlaneMatrix> lu(m0);
  lu.setThreshold(kSingularPivot);
  if (lu.rank() < m) return out;

  // dgamma(c) = g0 - g1 c.
  const PlaneMultipliers g0 = lu.solve(PlaneMultipliers(a * trial - r_0));
  const PlaneMultipliers g1 = lu.solve(r_c);
  const double h_g0 = h.dot(g0), h_g1 = h.dot(g1);

  // eps_p at the end. Without hardening planes (all weights 0, e.g. the tension cut-off)
  // or with a constant cohesion it follows directly; otherwise from g(e) = 0.
  const double e_direct = eps_p_start + h_g0 - h_g1 * law.value(eps_p_start);
  double e = e_direct;
  if (!law.constant() && h.cwiseAbs().maxCoeff() > 0.0) {
    // g(e) = eps_p_start + h.g0 - h.g1 c(e) - e, decreasing while softening is not too steep.
    auto g = [&](double x, double* dg) {
      *dg = -h_g1 * law.slope(x) - 1.0;
      return eps_p_start + h_g0 - h_g1 * law.value(x) - x;
    };
    // Round-off of e is relative to its size (1e-15); g is a strain, so the same bound
    // serves. g(eps_p_start) = e_direct - eps_p_start below it means no plastic eps_p: a
    // set with a negative multiplier, which the caller rejects.
    const double g_start = e_direct - eps_p_start;
    const double tol = 1e-15 * std::max(std::abs(eps_p_start) + std::abs(g_start), 1e-300);
    e = eps_p_start;
    if (g_start > tol) {
      const ScalarRoot root = find_root_above(g, eps_p_start, g_start, tol, tol);
      if (!root.converged) return out;
      e = root.x;
    }
  }
  const double c = law.value(e);
  out.multipliers = g0 - g1 * c;
  out.eps_p = std::max(e, eps_p_start);
  out.stress = trial - de_b * out.multipliers;

  const PlaneMatrix mh = m0 + law.slope(e) * r_c * h.transpose();
  Eigen::FullPivLU<PlaneMatrix> lu_h(mh);
  lu_h.setThreshold(kSingularPivot);
  if (lu_h.rank() < m) return out;  // softening exactly cancelling the elastic stiffness
  out.derivative = Mat3::Identity() - de_b * lu_h.solve(PlaneMatrix(a));
  out.solved = true;
  return out;
}

}  // namespace dda
