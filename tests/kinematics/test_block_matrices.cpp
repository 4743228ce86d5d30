// kinematics/block_matrices: Shi's T, the mass matrix against an independent quadrature, and
// the secant and sine rotation columns against the exact rotation.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kinematics/block_matrices.hpp"
#include "kinematics/polygon.hpp"
#include "support/scene_builders.hpp"

using namespace dda;
using Catch::Matchers::WithinRel;

TEST_CASE("T matrix is Shi's Eq. 3", "[kinematics]") {
  const Mat26 t = shi_t().at({0.3, -0.7});  // X = 0.3, Y = -0.7
  Mat26 expected;
  expected << 1, 0, 0.7, 0.3, 0, -0.35,  //
      0, 1, 0.3, 0, -0.7, 0.15;
  CHECK((t - expected).cwiseAbs().maxCoeff() == 0.0);
}

namespace {

// Independent reference for int rho T^T T dA: split the polygon into triangles fanned from
// `apex` (a point that sees every vertex) and use the three-edge-midpoint rule, exact for
// quadratics (T^T T is quadratic in x, y). No polygon moments are used.
Mat6 mass_by_quadrature(const Polygon& poly, const Vec2& apex, double rho) {
  const Vec2 reference = polygon_moments(poly).centroid;  // T's reference point only
  const LinearT t = shi_t();
  Mat6 m = Mat6::Zero();
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 a = apex, b = poly[i], c = poly[(i + 1) % poly.size()];
    const double area = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    for (const Vec2& q : {Vec2((a + b) / 2), Vec2((b + c) / 2), Vec2((c + a) / 2)}) {
      const Mat26 tq = t.at(q - reference);
      m += rho * area / 3.0 * tq.transpose() * tq;
    }
  }
  return m;
}

}  // namespace

TEST_CASE("mass matrix matches numerical quadrature", "[kinematics]") {
  const double rho = 2700.0;
  struct Case {
    Polygon poly;
    Vec2 apex;
  };
  const std::vector<Case> cases = {
      {test::rectangle(1, 2, 3, 0.5), {2.5, 2.25}},
      {{{0, 0}, {3, 0}, {0, 6}}, {1, 2}},
      {test::regular_polygon(8, 0.5, {1, 1}, 0.2), {1, 1}},
      {test::l_shape(), {5.0 / 6.0, 5.0 / 6.0}},  // the centroid sees all six vertices
  };
  for (const Case& c : cases) {
    const Mat6 exact = mass_matrix(shi_t(), polygon_moments(c.poly), rho);
    const Mat6 quad = mass_by_quadrature(c.poly, c.apex, rho);
    // Both are exact integrals; they differ by summation round-off (~1e-15 of the largest entry).
    CHECK((exact - quad).cwiseAbs().maxCoeff() <= 1e-13 * exact.cwiseAbs().maxCoeff());
    CHECK((exact - exact.transpose()).cwiseAbs().maxCoeff() == 0.0);
  }
}

namespace {
Mat2 rotation(double r) {
  return (Mat2() << std::cos(r), -std::sin(r), std::sin(r), std::cos(r)).finished();
}
}  // namespace

TEST_CASE("secant and sine rotation columns move points by the exact rotation", "[kinematics]") {
  // (R(r) - I) x is the exact displacement of a point x (from the reference point) turned
  // by r. With the secant column and d_r0 = r, or the sine column and d_r0 = sin r, T d must
  // give it to round-off (a few ulps of |x| = 5).
  const Vec2 offset(3.0, -4.0);
  for (const double r : {1e-9, 1e-4, 0.01, 0.3, -0.7, 1.2}) {
    Vec6 d = Vec6::Zero();
    d[kR0] = r;
    const Vec2 exact = (rotation(r) - Mat2::Identity()) * offset;
    const Vec2 secant = t_with_rotation_column(secant_rotation_column(r)).at(offset) * d;
    CHECK((secant - exact).norm() < 1e-14 * offset.norm());
    d[kR0] = std::sin(r);
    const Vec2 sine = t_with_rotation_column(sine_rotation_column(r)).at(offset) * d;
    CHECK((sine - exact).norm() < 1e-14 * offset.norm());
  }
}

TEST_CASE("the secant column is Shi's column at zero angle and tends to it", "[kinematics]") {
  // At r = 0 the secant column is J exactly, so finite_rotation starts from Shi's T bit for
  // bit; near 0 it differs from J by O(r) (diagonal -r/2) and O(r^2) (off-diagonal).
  CHECK(secant_rotation_column(0.0) == quarter_turn());
  CHECK(shi_t().dy(0, kR0) == -1.0);
  CHECK(shi_t().dx(1, kR0) == 1.0);
  const double r = 1e-3;
  const Mat2 a = secant_rotation_column(r);
  CHECK_THAT(a(0, 0), WithinRel(-r / 2.0, 1e-6));    // -(1 - cos r)/r = -r/2 + O(r^3)
  CHECK_THAT(a(1, 0), WithinRel(1.0 - r * r / 6.0, 1e-12));  // sin r / r
}
