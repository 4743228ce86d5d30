#include "materials/elastic.hpp"

#include <cassert>

namespace dda {

Mat3 elastic_matrix(double young, double poisson, PlaneMode plane) {
  assert(young > 0.0 && poisson > -1.0 && poisson < 0.5);
  Mat3 d = Mat3::Zero();
  if (plane == PlaneMode::Stress) {
    const double c = young / (1.0 - poisson * poisson);
    d << c, c * poisson, 0.0,  //
        c * poisson, c, 0.0,   //
        0.0, 0.0, c * (1.0 - poisson) / 2.0;
  } else {
    const double c = young / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
    d << c * (1.0 - poisson), c * poisson, 0.0,  //
        c * poisson, c * (1.0 - poisson), 0.0,   //
        0.0, 0.0, c * (1.0 - 2.0 * poisson) / 2.0;
  }
  return d;
}

}  // namespace dda
