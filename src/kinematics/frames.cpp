#include "kinematics/frames.hpp"

#include <cmath>

namespace dda {

Vec3 strain_in_turned_frame(const Vec3& e, double theta) {
  // E' = Q E Q^T with the turned axes as the rows of Q: x' = (c, s), y' = (-s, c). Written
  // with c and s rather than 2 theta so that theta = 0 returns e bit for bit.
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  const double half_g = 0.5 * e[2];
  const double exx = c * c * e[0] + 2.0 * c * s * half_g + s * s * e[1];
  const double eyy = s * s * e[0] - 2.0 * c * s * half_g + c * c * e[1];
  const double exy = -c * s * e[0] + (c * c - s * s) * half_g + c * s * e[1];
  return Vec3(exx, eyy, 2.0 * exy);
}

Vec3 strain_from_turned_frame(const Vec3& e_turned, double theta) {
  return strain_in_turned_frame(e_turned, -theta);
}

// A stress vector is a strain vector with half the shear: doubling and halving the shear
// are exact in binary, so the stress maps inherit the strain maps' round-off.
Vec3 stress_in_turned_frame(const Vec3& s, double theta) {
  const Vec3 as_strain = strain_in_turned_frame(Vec3(s[0], s[1], 2.0 * s[2]), theta);
  return Vec3(as_strain[0], as_strain[1], 0.5 * as_strain[2]);
}

Vec3 stress_from_turned_frame(const Vec3& s_turned, double theta) {
  return stress_in_turned_frame(s_turned, -theta);
}

}  // namespace dda
