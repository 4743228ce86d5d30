#include "kinematics/block_matrices.hpp"

namespace dda {

LinearT shi_t() {
  LinearT t;
  t.constant(0, kU0) = 1.0;
  t.constant(1, kV0) = 1.0;
  // Column r0: (-Y, X).
  t.dy(0, kR0) = -1.0;
  t.dx(1, kR0) = 1.0;
  // Strains: u = X ex + Y gxy/2, v = Y ey + X gxy/2.
  t.dx(0, kEx) = 1.0;
  t.dy(1, kEy) = 1.0;
  t.dy(0, kGxy) = 0.5;
  t.dx(1, kGxy) = 0.5;
  return t;
}

Mat6 mass_matrix(const LinearT& t, const Moments& m, double density) {
  // int (C + X Dx + Y Dy)^T (C + X Dx + Y Dy) dA with int X = int Y = 0 about the centroid.
  const Mat6 integral = m.area * t.constant.transpose() * t.constant +  //
                        m.sxx * t.dx.transpose() * t.dx +              //
                        m.syy * t.dy.transpose() * t.dy +              //
                        m.sxy * (t.dx.transpose() * t.dy + t.dy.transpose() * t.dx);
  return density * integral;
}

Mat6 elastic_stiffness(const Moments& m, const Mat3& d) {
  Mat6 k = Mat6::Zero();
  k.block<3, 3>(kEx, kEx) = m.area * d;
  return k;
}

Vec6 body_force(const LinearT& t, const Moments& m, double density, const Vec2& g) {
  return density * m.area * t.constant.transpose() * g;
}

Vec6 initial_stress_force(const Moments& m, const Vec3& stress) {
  Vec6 f = Vec6::Zero();
  f.segment<3>(kEx) = -m.area * stress;
  return f;
}

Vec6 point_force(const Mat26& t_at_point, const Vec2& f) { return t_at_point.transpose() * f; }

Mat6 spring_stiffness(const Mat26& t_at_point, double p) {
  return p * t_at_point.transpose() * t_at_point;
}

Vec6 spring_force(const Mat26& t_at_point, double p, const Vec2& gap) {
  return p * t_at_point.transpose() * gap;
}

}  // namespace dda
