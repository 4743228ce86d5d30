// A yield surface made of planes in sorted principal stress space (s1 >= s2 >= s3), and the
// return of a trial stress onto a set of them (the active set) with cohesion hardening.
//
// Plane k: f_k = n_k . s - (cohesion_factor_k c(eps_p) + constant_k), plastic flow
// d e_p = d gamma_k flow_k in principal axes, d eps_p = hardening_weight_k d gamma_k.
// Mohr-Coulomb planes and the tension cut-off are of this form (yield_mohr_coulomb.hpp).
#pragma once

#include <span>

#include "kinematics/types.hpp"
#include "materials/hardening.hpp"

namespace dda {

struct PrincipalPlane {
  Vec3 normal = Vec3::Zero();
  Vec3 flow = Vec3::Zero();
  double cohesion_factor = 0.0;
  double constant = 0.0;
  double hardening_weight = 0.0;

  double value(const Vec3& s, double cohesion) const {
    return normal.dot(s) - cohesion_factor * cohesion - constant;
  }
};

constexpr int kMaxActivePlanes = 3;
using PlaneMultipliers = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxActivePlanes, 1>;

struct PlanesReturn {
  bool solved = false;         // false: the active set's system is singular, or no root
  Vec3 stress = Vec3::Zero();  // returned (s1, s2, s3)
  PlaneMultipliers multipliers;
  double eps_p = 0.0;              // at the end of the step
  Mat3 derivative = Mat3::Zero();  // d(returned) / d(trial), in sorted order
};

// Returns `trial` (sorted principal stresses) onto all `planes` at once: the closest point
// in the energy norm of the flow (de Souza Neto et al. 2008, ch. 8, generalised to any set of
// planes). elastic is the principal elastic matrix (lambda 1 1^T + 2G I).
//
// The multipliers solve  A (trial - De B dgamma) = r(c),  r_k = cohesion_factor_k c +
// constant_k,  with c = c(eps_p_start + h . dgamma). They are affine in c, so the one
// nonlinear unknown is eps_p at the end: Newton on
//   g(e) = eps_p_start + h . dgamma(c(e)) - e = 0
// (scalar_root.hpp) is Newton on the multipliers reduced to one equation. The derivative is
// I - De B M^-1 A with M = A De B + c'(e) r_c h^T.
PlanesReturn return_to_planes(std::span<const PrincipalPlane> planes, const Vec3& trial,
                              const Mat3& elastic, double eps_p_start, const CohesionLaw& law);

}  // namespace dda
