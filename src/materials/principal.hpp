// Principal stresses of a plane-strain stress (szz is always principal) and the derivative
// of an isotropic stress map (a return map) rotated back from principal axes.
#pragma once

#include <array>

#include "kinematics/types.hpp"
#include "materials/voigt4.hpp"

namespace dda {

struct PrincipalStress {
  Vec3 abz = Vec3::Zero();  // (s_a, s_b, szz): the in-plane pair with s_a >= s_b, then szz
  double angle = 0.0;       // direction of a, from x (radians)
  // order[k] is the index into abz of the k-th largest: s1 >= s2 >= s3 (tension positive).
  // Ties keep the abz order, so the sort is repeatable.
  std::array<int, 3> order = {0, 1, 2};

  Vec3 sorted() const { return {abz[order[0]], abz[order[1]], abz[order[2]]}; }
  // From sorted (s1, s2, s3) back to (a, b, z) positions, for values and derivatives.
  Vec3 unsort(const Vec3& sorted) const;
  Mat3 unsort(const Mat3& sorted_derivative) const;
};

PrincipalStress principal_stress(const Vec4& s);

// The stress with principal values abz, a along `angle`.
Vec4 stress_from_principal(const Vec3& abz, double angle);

// d s / d s_trial (4x4, stress to stress, Voigt as voigt4.hpp) of an isotropic map that
// keeps the trial's principal axes, given the returned principal values (abz) and their
// derivatives d(abz) / d(abz_trial). The in-plane spin term is (s_a - s_b) / (t_a - t_b)
// for distinct trial values t; when t_a - t_b <= repeated_tol it is replaced by its limit
// d s_a / d t_a - d s_a / d t_b (de Souza Neto et al. 2008, appendix A), because the
// quotient then loses its digits to cancellation.
Mat4 isotropic_derivative(const PrincipalStress& trial, const Vec3& returned_abz,
                          const Mat3& derivative_abz, double repeated_tol);

}  // namespace dda
