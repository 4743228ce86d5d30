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

}  // namespace dda
