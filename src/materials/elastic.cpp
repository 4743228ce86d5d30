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

ElasticModuli elastic_moduli(double young, double poisson) {
  assert(young > 0.0 && poisson > -1.0 && poisson < 0.5);
  ElasticModuli m;
  m.young = young;
  m.shear = young / (2.0 * (1.0 + poisson));
  m.bulk = young / (3.0 * (1.0 - 2.0 * poisson));
  m.lame = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
  return m;
}

Mat4 elastic_matrix4(const ElasticModuli& m) {
  const double l = m.lame, g2 = 2.0 * m.shear;
  Mat4 d;
  d << l + g2, l, l, 0.0,  //
      l, l + g2, l, 0.0,   //
      l, l, l + g2, 0.0,   //
      0.0, 0.0, 0.0, m.shear;
  return d;
}

Vec4 elastic_compliance4(const ElasticModuli& m, const Vec4& s) {
  // e = dev(s) / 2G + tr(s) / (9K) 1; engineering shear gxy = sxy / G.
  const double p = mean_stress(s);
  const double vol = p / (3.0 * m.bulk);
  const double g2 = 2.0 * m.shear;
  return {(s[kXX] - p) / g2 + vol, (s[kYY] - p) / g2 + vol, (s[kZZ] - p) / g2 + vol,
          s[kXY] / m.shear};
}

}  // namespace dda
