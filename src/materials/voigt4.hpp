// Four-component Voigt vectors for plane strain with the out-of-plane component kept:
// stress (sxx, syy, szz, sxy) with tensor shear, strain (exx, eyy, ezz, gxy) with
// engineering shear gxy = 2 exy, so that stress . strain is the work density.
// Tension positive.
#pragma once

#include <Eigen/Dense>

#include "kinematics/types.hpp"

namespace dda {

using Vec4 = Eigen::Vector4d;
using Mat4 = Eigen::Matrix4d;

// Index of each component in a Vec4.
enum Voigt4 : int { kXX = 0, kYY = 1, kZZ = 2, kXY = 3 };

// The in-plane rows and columns (xx, yy, xy) of a 4-component quantity.
inline Vec3 in_plane(const Vec4& v) { return {v[kXX], v[kYY], v[kXY]}; }
inline Mat3 in_plane(const Mat4& m) {
  const int idx[3] = {kXX, kYY, kXY};
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = m(idx[i], idx[j]);
  return r;
}

// Plane-strain total strain (exx, eyy, gxy) as a 4-component strain with ezz = 0.
inline Vec4 plane_strain4(const Vec3& e) { return {e[0], e[1], 0.0, e[2]}; }

// Mean stress p = tr(s) / 3.
inline double mean_stress(const Vec4& s) { return (s[kXX] + s[kYY] + s[kZZ]) / 3.0; }

// Deviator s - p 1 (the shear component is unchanged).
inline Vec4 deviator(const Vec4& s) {
  const double p = mean_stress(s);
  return {s[kXX] - p, s[kYY] - p, s[kZZ] - p, s[kXY]};
}

// J2 = s':s' / 2 of a stress; the shear counts twice in the double contraction.
inline double j2_invariant(const Vec4& s) {
  const Vec4 d = deviator(s);
  return 0.5 * (d[kXX] * d[kXX] + d[kYY] * d[kYY] + d[kZZ] * d[kZZ]) + d[kXY] * d[kXY];
}

}  // namespace dda
