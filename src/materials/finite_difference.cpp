#include "materials/finite_difference.hpp"

namespace dda {

Mat3 finite_difference_tangent(const MaterialParameters& params, const MaterialState& start,
                               const Vec3& total_strain, const Vec4& initial_stress, double h) {
  Mat3 d;
  for (int j = 0; j < 3; ++j) {
    Vec3 up = total_strain, down = total_strain;
    up[j] += h;
    down[j] -= h;
    const Vec4 s_up = integrate(params, start, up, initial_stress).stress;
    const Vec4 s_down = integrate(params, start, down, initial_stress).stress;
    d.col(j) = (in_plane(s_up) - in_plane(s_down)) / (2.0 * h);
  }
  return d;
}

}  // namespace dda
