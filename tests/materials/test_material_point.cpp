// The elastic model through integrate(), the material-point driver's path semantics, and
// quadratic convergence of its Newton solve with the consistent tangent.
#include <catch2/catch.hpp>

#include "support/material_builders.hpp"
#include <cmath>
#include <vector>

#include "materials/material.hpp"
#include "materials/material_point.hpp"

using namespace dda;
using test::segment;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

MaterialParameters elastic(PlaneMode plane) {
  MaterialParameters p;
  test::set_model(p, MaterialModel::Elastic);
  p.young = 2e9;
  p.poisson = 0.2;
  p.density = 2500.0;
  p.plane = plane;
  return p;
}


// A few flops on numbers ~1e6: 1e-14 relative.
constexpr double kRoundOff = 1e-14;

}  // namespace

TEST_CASE("elastic material: plane strain and plane stress by hand", "[materials]") {
  const double e = 2e9, nu = 0.2;
  const Vec3 strain{1e-4, -3e-4, 2e-4};
  const Vec4 s0{-1e5, -2e5, -0.6e5, 3e4};
  {
    // Plane strain: s = s0 + lambda tr(e) 1 + 2 G e, szz = s0zz + lambda tr(e).
    const double g = e / (2.0 * (1.0 + nu)), lame = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    const double tr = strain[0] + strain[1];
    const MaterialResult r = integrate(elastic(PlaneMode::Strain), {}, strain, s0);
    CHECK(r.status.converged);
    CHECK(r.branch == Branch::Elastic);
    CHECK_THAT(r.stress[kXX], WithinRel(s0[kXX] + lame * tr + 2.0 * g * strain[0], kRoundOff));
    CHECK_THAT(r.stress[kYY], WithinRel(s0[kYY] + lame * tr + 2.0 * g * strain[1], kRoundOff));
    CHECK_THAT(r.stress[kZZ], WithinRel(s0[kZZ] + lame * tr, kRoundOff));
    CHECK_THAT(r.stress[kXY], WithinRel(s0[kXY] + g * strain[2], kRoundOff));
    CHECK(r.tangent.isApprox(elastic_matrix(e, nu, PlaneMode::Strain), kRoundOff));
    CHECK(r.state.plastic_strain.isZero());
  }
  {
    // Plane stress: s = s0 + E / (1 - nu^2) [e_xx + nu e_yy, ...], szz = 0.
    const double c = e / (1.0 - nu * nu);
    const MaterialResult r = integrate(elastic(PlaneMode::Stress), {}, strain, s0);
    CHECK(r.status.converged);
    CHECK_THAT(r.stress[kXX], WithinRel(s0[kXX] + c * (strain[0] + nu * strain[1]), kRoundOff));
    CHECK_THAT(r.stress[kYY], WithinRel(s0[kYY] + c * (strain[1] + nu * strain[0]), kRoundOff));
    CHECK(r.stress[kZZ] == 0.0);
    CHECK_THAT(r.stress[kXY], WithinRel(s0[kXY] + c * (1.0 - nu) / 2.0 * strain[2], kRoundOff));
    CHECK(r.tangent.isApprox(elastic_matrix(e, nu, PlaneMode::Stress), kRoundOff));
  }
}

TEST_CASE("plastic models refuse plane stress", "[materials]") {
  MaterialParameters p = elastic(PlaneMode::Stress);
  test::set_model(p, MaterialModel::MohrCoulomb);
  test::strength_of(p).cohesion = 1e6;
  test::strength_of(p).friction_angle = 30.0;
  const MaterialResult r = integrate(p, {}, {1e-3, 0.0, 0.0});
  CHECK_FALSE(r.status.converged);
  CHECK(r.status.suggested_fraction == 0.0);
}

TEST_CASE("material-point path: mixed control, held components, step rows", "[materials]") {
  // Elastic plane strain, so every point is a closed form: e = D^-1 (s - s0) on the
  // stress-controlled components.
  const MaterialParameters p = elastic(PlaneMode::Strain);
  const Mat3 d = elastic_matrix(p.young, p.poisson, PlaneMode::Strain);
  const Vec4 s0{-1e5, -1e5, -0.4e5, 0.0};
  const std::vector<PathSegment> path = {
      // 1: sxx held at its initial -1e5 by stress, eyy to -1e-3, gxy (not named) strain 0.
      segment(4, ComponentTarget{Control::Stress, -1e5}, ComponentTarget{Control::Strain, -1e-3},
              {}),
      // 2: only the shear is named (stress 1e5); sxx stays stress-held at -1e5, eyy at -1e-3.
      segment(2, {}, {}, ComponentTarget{Control::Stress, 1e5}),
  };
  const MaterialPointRun r = run_material_point(p, s0, path);
  REQUIRE(r.ok);
  REQUIRE(r.rows.size() == 7);  // the start and 4 + 2 increments
  CHECK(r.rows[0].step == 0);
  CHECK(r.rows[0].strain.isZero());
  CHECK(r.rows[0].stress == s0);
  for (int k = 1; k <= 6; ++k) CHECK(r.rows[k].step == k);
  // Segment 1, increment 2: eyy = -0.5e-3; sxx = -1e5 means d00 exx + d01 eyy = 0.
  const MaterialPointRow& mid = r.rows[2];
  CHECK_THAT(mid.strain[1], WithinRel(-0.5e-3, kRoundOff));
  CHECK_THAT(mid.strain[0], WithinRel(-d(0, 1) / d(0, 0) * -0.5e-3, 1e-10));  // Newton tol
  CHECK(mid.strain[2] == 0.0);
  // The end: sxy = 1e5 from gxy = 1e5 / G; eyy still -1e-3; sxx still -1e5.
  const MaterialPointRow& end = r.rows.back();
  CHECK_THAT(end.stress[kXY], WithinRel(1e5, 1e-10));
  CHECK_THAT(end.strain[2], WithinRel(1e5 / d(2, 2), 1e-10));
  CHECK_THAT(end.strain[1], WithinRel(-1e-3, kRoundOff));
  CHECK_THAT(end.stress[kXX], WithinRel(-1e5, 1e-10));
  // Halfway through segment 2: sxy = 0.5e5 (linear from 0 to the target).
  CHECK_THAT(r.rows[5].stress[kXY], WithinRel(0.5e5, 1e-10));
}

TEST_CASE("material-point Newton converges quadratically with the consistent tangent",
          "[materials]") {
  // Mixed control on curved returns: sxx and sxy held by stress while eyy is pushed, with
  // hardening. Residuals rho_k = r_k / S (S = 1e5 Pa, the stress scale). Quadratic
  // convergence: rho_{k+1} <= K rho_k^2 with K of the order of the return's curvature
  // relative to S; K = 10 bounds what is seen (~1) with room, and is far below what
  // linear convergence gives (rho_{k+1} / rho_k^2 = q / rho_k > 1e3 once rho_k < 1e-4).
  // Pairs whose rho_{k+1} is below 1e-12 (round-off of the returns) are not judged.
  const double scale = 1e5;
  for (const MaterialModel model : {MaterialModel::DruckerPrager, MaterialModel::MohrCoulomb}) {
    MaterialParameters p = test::soil(model, 10.0);
    test::strength_of(p).hardening = {{0.0, 20e3}, {0.05, 40e3}};
    const std::vector<PathSegment> path = {segment(10, ComponentTarget{Control::Stress, -1e5},
                                                   ComponentTarget{Control::Strain, -0.02},
                                                   ComponentTarget{Control::Stress, 3e4})};
    const MaterialPointRun r = run_material_point(p, {-1e5, -1e5, -0.6e5, 0.0}, path);
    REQUIRE(r.ok);
    int judged = 0, multi = 0;
    for (const MaterialPointRow& row : r.rows) {
      if (row.residuals.size() >= 3) ++multi;
      for (std::size_t k = 0; k + 1 < row.residuals.size(); ++k) {
        const double a = row.residuals[k] / scale, b = row.residuals[k + 1] / scale;
        if (b < 1e-12) continue;
        ++judged;
        INFO("step " << row.step << ": rho " << a << " -> " << b);
        CHECK(b <= 10.0 * a * a);
      }
    }
    CHECK(multi >= 3);    // the solves took several iterations ...
    CHECK(judged >= 10);  // ... enough to judge
  }
}

TEST_CASE("the quadratic-convergence check fails for an elastic-tangent Newton", "[materials]") {
  // The same kind of solve with the elastic tangent instead of the consistent one: it
  // converges only linearly, and rho_{k+1} <= 10 rho_k^2 is broken. This shows the test
  // above can fail.
  const MaterialParameters p = test::soil(MaterialModel::DruckerPrager, 10.0);
  const Vec4 s0{-1e5, -1e5, -0.6e5, 0.0};
  const Mat3 d = elastic_matrix(p.young, p.poisson, PlaneMode::Strain);
  // sxx = -1e5 and sxy = 3e4 by stress at eyy = -5e-3 (on the cone).
  Vec3 e{0.0, -5e-3, 0.0};
  const double scale = 1e5;
  bool broken = false;
  double prev = 0.0;
  for (int it = 0; it < 30; ++it) {
    const MaterialResult r = integrate(p, {}, e, s0);
    const Vec2 res{r.stress[kXX] + 1e5, r.stress[kXY] - 3e4};
    const double rho = res.norm() / scale;
    if (it > 0 && rho > 1e-12 && rho > 10.0 * prev * prev) broken = true;
    prev = rho;
    Mat2 j;
    j << d(0, 0), d(0, 2), d(2, 0), d(2, 2);
    const Vec2 de = j.lu().solve(-res);
    e[0] += de[0];
    e[2] += de[1];
  }
  CHECK(broken);
}
