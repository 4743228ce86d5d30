#include "materials/principal.hpp"

#include <algorithm>
#include <cmath>

namespace dda {

namespace {

// Maps a global stress (xx, yy, zz, xy) to its components in axes (a, b, z), a at `angle`.
Mat4 stress_rotation(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Mat4 t;
  t << c * c, s * s, 0.0, 2.0 * c * s,  //
      s * s, c * c, 0.0, -2.0 * c * s,  //
      0.0, 0.0, 1.0, 0.0,               //
      -c * s, c * s, 0.0, c * c - s * s;
  return t;
}

}  // namespace

Vec3 PrincipalStress::unsort(const Vec3& sorted) const {
  Vec3 r;
  for (int k = 0; k < 3; ++k) r[order[k]] = sorted[k];
  return r;
}

Mat3 PrincipalStress::unsort(const Mat3& d) const {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(order[i], order[j]) = d(i, j);
  return r;
}

PrincipalStress principal_stress(const Vec4& s) {
  PrincipalStress p;
  const double mean = 0.5 * (s[kXX] + s[kYY]);
  const double half = 0.5 * (s[kXX] - s[kYY]);
  const double radius = std::hypot(half, s[kXY]);
  p.abz = {mean + radius, mean - radius, s[kZZ]};
  p.angle = 0.5 * std::atan2(s[kXY], half);  // atan2(0, 0) = 0: any axes do for a circle
  std::stable_sort(p.order.begin(), p.order.end(),
                   [&](int i, int j) { return p.abz[i] > p.abz[j]; });
  return p;
}

Vec4 stress_from_principal(const Vec3& abz, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * c * abz[0] + s * s * abz[1], s * s * abz[0] + c * c * abz[1], abz[2],
          c * s * (abz[0] - abz[1])};
}

Mat4 isotropic_derivative(const PrincipalStress& trial, const Vec3& returned_abz,
                          const Mat3& derivative_abz, double repeated_tol) {
  Mat4 l = Mat4::Zero();
  l.topLeftCorner<3, 3>() = derivative_abz;
  const double gap = trial.abz[0] - trial.abz[1];
  l(kXY, kXY) = gap > repeated_tol ? (returned_abz[0] - returned_abz[1]) / gap
                                   : derivative_abz(0, 0) - derivative_abz(0, 1);
  return stress_rotation(-trial.angle) * l * stress_rotation(trial.angle);
}

}  // namespace dda
