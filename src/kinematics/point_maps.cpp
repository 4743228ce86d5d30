#include "kinematics/point_maps.hpp"

#include <cmath>

namespace dda {
namespace {

// Eq. (8) with the rotation entering through cos r0 - 1 and sin r0.
Vec2 eq8_displacement(const Vec2& offset, const Vec6& db, double cos_minus_one, double sin_r) {
  const double x = offset.x();
  const double y = offset.y();
  return Vec2(db[kU0] + x * cos_minus_one - y * sin_r + x * db[kEx] + 0.5 * y * db[kGxy],
              db[kV0] + x * sin_r + y * cos_minus_one + y * db[kEy] + 0.5 * x * db[kGxy]);
}

}  // namespace

Mat2 strain_tensor(const Vec3& e) {
  Mat2 m;
  m << e[0], 0.5 * e[2], 0.5 * e[2], e[1];
  return m;
}

Mat2 rotation_matrix(double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  Mat2 m;
  m << c, -s, s, c;
  return m;
}

Vec2 second_order_displacement(const Vec2& offset, const Vec6& db) {
  const double r = db[kR0];
  return eq8_displacement(offset, db, -0.5 * r * r, r);
}

Vec2 finite_rotation_displacement(const Vec2& offset, const Vec6& db) {
  const double r = db[kR0];
  // cos r - 1 as -2 sin^2(r/2): accurate to relative round-off for the small angles of a
  // step, where 1 - cos r would lose the leading digits.
  const double half_sin = std::sin(0.5 * r);
  return eq8_displacement(offset, db, -2.0 * half_sin * half_sin, std::sin(r));
}

Mat2 frame_map(double r, const Vec3& local_strain) {
  return rotation_matrix(r) * (Mat2::Identity() + strain_tensor(local_strain));
}

Mat2 frame_map_as_printed(double r, const Vec3& local_strain) {
  const Mat2 rot = rotation_matrix(r);
  return rot + rot * strain_tensor(local_strain) * rot.transpose();
}

PolarDecomposition polar_decomposition(const Mat2& f, double near) {
  // In 2D the rotation of F = R U is the angle of (F00 + F11, F10 - F01): R^T F symmetric
  // means its antisymmetric part, cos t (F10 - F01) - sin t (F00 + F11), vanishes; with
  // det F > 0 the sign that makes U positive definite is the one with trace(R^T F) > 0.
  const double principal = std::atan2(f(1, 0) - f(0, 1), f(0, 0) + f(1, 1));
  const double two_pi = 2.0 * M_PI;
  PolarDecomposition p;
  p.angle = principal + two_pi * std::round((near - principal) / two_pi);
  const Mat2 u = rotation_matrix(-principal) * f;
  const double off = 0.5 * (u(0, 1) + u(1, 0));  // symmetric to round-off
  p.strain = Vec3(u(0, 0) - 1.0, u(1, 1) - 1.0, 2.0 * off);
  return p;
}

}  // namespace dda
