#include "kinematics/block_matrices.hpp"

#include <cassert>
#include <cmath>

namespace dda {

Mat2 quarter_turn() { return (Mat2() << 0.0, -1.0, 1.0, 0.0).finished(); }

const LinearT& shi_t() {
  static const LinearT t = t_with_rotation_column(quarter_turn());
  return t;
}

Mat2 secant_rotation_column(double r) {
  if (r == 0.0) return quarter_turn();
  // (cos r - 1)/r written as -2 sin^2(r/2)/r: no cancellation for small r.
  const double diagonal = -2.0 * std::sin(0.5 * r) * std::sin(0.5 * r) / r;
  const double off = std::sin(r) / r;
  return (Mat2() << diagonal, -off, off, diagonal).finished();
}

Mat2 sine_rotation_column(double r) {
  assert(std::abs(r) < 0.5 * M_PI);
  // (cos r - 1)/sin r = -tan(r/2).
  const double diagonal = -std::tan(0.5 * r);
  return (Mat2() << diagonal, -1.0, 1.0, diagonal).finished();
}

Mat2 rotation_column(const LinearT& t) {
  return (Mat2() << t.dx(0, kR0), t.dy(0, kR0), t.dx(1, kR0), t.dy(1, kR0)).finished();
}

LinearT t_with_rotation_column(const Mat2& a) {
  LinearT t;
  t.constant(0, kU0) = 1.0;
  t.constant(1, kV0) = 1.0;
  // Column r0: a (X, Y); Shi's (-Y, X) when a = J.
  t.dx(0, kR0) = a(0, 0);
  t.dx(1, kR0) = a(1, 0);
  t.dy(0, kR0) = a(0, 1);
  t.dy(1, kR0) = a(1, 1);
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
