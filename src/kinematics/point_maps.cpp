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

namespace {

// atanh(x) / x and sinh(q) / q, by their series below 1e-4 (the next term, x^6/7 or
// q^6/5040, is then below 1e-24 of 1).
double atanh_over(double x) {
  if (std::abs(x) < 1e-4) return 1.0 + x * x / 3.0 + x * x * x * x / 5.0;
  return std::atanh(x) / x;
}
double sinh_over(double q) {
  if (q < 1e-4) return 1.0 + q * q / 6.0 + q * q * q * q / 120.0;
  return std::sinh(q) / q;
}

// The mean diagonal m and half the eigenvalue spread q of a symmetric [ex, ey, gxy] tensor
// (shear on the off-diagonals as gxy / 2).
struct Spread {
  double mean;
  double half;
};
Spread spread_of(double xx, double yy, double xy) {
  return {0.5 * (xx + yy), std::hypot(0.5 * (xx - yy), xy)};
}

}  // namespace

Vec3 hencky_from_stretch(const Vec3& biot) {
  // S = I + E: mean 1 + mu, spread q; ln S = a I + b (S - (1 + mu) I), with
  // a = ln((1 + mu)^2 - q^2) / 2 taken by log1p (strains of 1e-6 keep their digits).
  const Spread s = spread_of(biot[0], biot[1], 0.5 * biot[2]);
  const double m = 1.0 + s.mean;
  const double b = atanh_over(s.half / m) / m;
  const double a = 0.5 * std::log1p(2.0 * s.mean + s.mean * s.mean - s.half * s.half);
  return Vec3(a + b * (biot[0] - s.mean), a + b * (biot[1] - s.mean), b * biot[2]);
}

Vec3 stretch_from_hencky(const Vec3& hencky) {
  const Spread s = spread_of(hencky[0], hencky[1], 0.5 * hencky[2]);
  const double e = std::exp(s.mean);
  const double b = e * sinh_over(s.half);
  // exp(H) - I = c I + b (H - m I), c = e^m cosh q - 1 = expm1(m) + e^m 2 sinh^2(q/2).
  const double sh = std::sinh(0.5 * s.half);
  const double c = std::expm1(s.mean) + 2.0 * e * sh * sh;
  return Vec3(c + b * (hencky[0] - s.mean), c + b * (hencky[1] - s.mean), b * hencky[2]);
}

Mat2 hencky_frame_map(double r, const Vec3& hencky) {
  return rotation_matrix(r) * (Mat2::Identity() + strain_tensor(stretch_from_hencky(hencky)));
}

}  // namespace dda
