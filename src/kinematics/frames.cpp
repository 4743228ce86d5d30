#include "kinematics/frames.hpp"

#include <cmath>

namespace dda {

Vec3 strain_in_turned_frame(const Vec3& e, double theta) {
  const double c = std::cos(2.0 * theta);
  const double s = std::sin(2.0 * theta);
  const double mean = 0.5 * (e[0] + e[1]);
  const double half_diff = 0.5 * (e[0] - e[1]);
  return Vec3(mean + half_diff * c + 0.5 * e[2] * s,  //
              mean - half_diff * c - 0.5 * e[2] * s,  //
              -2.0 * half_diff * s + e[2] * c);
}

}  // namespace dda
