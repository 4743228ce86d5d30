// Mohr-Coulomb closed forms (docs/closed-forms.md, "Mohr-Coulomb"), driven through the
// material-point driver (src/materials/material_point.hpp) in plane strain. Tension positive.
#include <catch2/catch.hpp>

#include "support/material_builders.hpp"
#include <cmath>
#include <numbers>
#include <vector>

#include "materials/material.hpp"
#include "materials/material_point.hpp"
#include "materials/principal.hpp"
#include "materials/yield_mohr_coulomb.hpp"

using namespace dda;
using test::segment;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// The driver stops Newton at 1e-10 of the stress scale on the stress-controlled components;
// a closed form that follows from them through the yield condition (a factor N <= 4 here)
// is then exact to a few 1e-10: 1e-9 relative.
constexpr double kDriverTol = 1e-9;

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180.0; }

// A soil-like Mohr-Coulomb material: E = 50 MPa, nu = 0.3, c = 20 kPa, phi = 30 degrees.
MaterialParameters soil(double dilation_deg) {
  return test::soil(MaterialModel::MohrCoulomb, dilation_deg);
}

ComponentTarget strain(double v) { return {Control::Strain, v}; }
ComponentTarget stress(double v) { return {Control::Stress, v}; }


MaterialPointRun run(const MaterialParameters& p, const Vec4& s0, std::vector<PathSegment> path) {
  MaterialPointRun r = run_material_point(p, s0, path);
  REQUIRE(r.ok);
  return r;
}

double flow_factor(double deg) { return (1.0 + std::sin(rad(deg))) / (1.0 - std::sin(rad(deg))); }

// Plane-strain biaxial test: lateral stress -p0 held, vertical strain pushed to -2 %.
constexpr double kP0 = 100e3;
MaterialPointRun biaxial(const MaterialParameters& p, int steps = 200, double eyy = -0.02) {
  const double szz0 = p.poisson * (-2.0 * kP0);  // plane-strain szz = nu (sxx + syy)
  return run(p, {-kP0, -kP0, szz0, 0.0}, {segment(steps, stress(-kP0), strain(eyy), strain(0.0))});
}

}  // namespace

TEST_CASE("Mohr-Coulomb plane-strain biaxial strength s1 = N s3 + 2 c sqrt(N)", "[materials]") {
  for (const double psi : {0.0, 10.0, 30.0}) {
    const MaterialParameters p = soil(psi);
    const MaterialPointRun r = biaxial(p);
    const double n = flow_factor(test::strength_of(p).friction_angle);
    // Compression magnitudes: major = N minor + 2 c sqrt(N).
    const double strength = n * kP0 + 2.0 * test::strength_of(p).cohesion * std::sqrt(n);
    int plastic = 0;
    for (const MaterialPointRow& row : r.rows) {
      // szz = nu (sxx + syy): elastically always, plastically while szz is intermediate
      // (the main plane's flow has no zz part). At the start szz (-60 kPa) is the major
      // stress; it is intermediate long before yield (once syy < -233 kPa).
      CHECK_THAT(row.stress[kZZ],
                 WithinRel(p.poisson * (row.stress[kXX] + row.stress[kYY]), kDriverTol));
      if (row.branch == Branch::Plane) {
        ++plastic;
        CHECK(row.stress[kZZ] < row.stress[kXX]);
        CHECK(row.stress[kZZ] > row.stress[kYY]);
        CHECK_THAT(-row.stress[kYY], WithinRel(strength, kDriverTol));
      } else {
        CHECK(row.branch == Branch::Elastic);
        CHECK(-row.stress[kYY] < strength * (1.0 + kDriverTol));
      }
    }
    // The elastic stretch takes (strength - p0) (1 - nu^2) / E ~ 1.1e-3 of the 2e-2: most
    // of the 200 increments are plastic.
    CHECK(plastic > 150);
    CHECK(r.rows.back().branch == Branch::Plane);
  }
}

TEST_CASE("Mohr-Coulomb plateau strain-increment ratio -(1 + sin psi) / (1 - sin psi)",
          "[materials]") {
  for (const double psi : {0.0, 10.0, 20.0, 30.0}) {
    const MaterialPointRun r = biaxial(soil(psi));
    const MaterialPointRow& a = r.rows[150];
    const MaterialPointRow& b = r.rows[200];
    REQUIRE(a.branch == Branch::Plane);
    // On the plateau the stress is constant, so the strain increments are plastic: e1 is
    // exx (sxx is the major stress), e3 is eyy. The elastic strain moves only by the Newton
    // tolerance on sxx (1e-10 of 1e5 Pa over E = 5e7 Pa: 2e-13 against increments of 5e-3),
    // so 1e-9 is ample.
    const double d1 = b.strain[0] - a.strain[0], d3 = b.strain[1] - a.strain[1];
    CHECK_THAT(d1 / d3, WithinRel(-flow_factor(psi), kDriverTol));
    // d eps_v^p / d gamma^p = sin psi, gamma^p = e1 - e3 (absolute: sin 0 = 0).
    CHECK_THAT((d1 + d3) / (d1 - d3), WithinAbs(std::sin(rad(psi)), kDriverTol));
    // eps_p is conjugate to c: d eps_p = cos(phi) (d e1^p - d e3^p) on the main plane.
    const double de1p = b.state.plastic_strain[kXX] - a.state.plastic_strain[kXX];
    const double de3p = b.state.plastic_strain[kYY] - a.state.plastic_strain[kYY];
    CHECK_THAT(b.state.eps_p - a.state.eps_p,
               WithinRel(std::cos(rad(30.0)) * (de1p - de3p), kDriverTol));
    CHECK_THAT(b.state.plastic_strain[kZZ], WithinAbs(0.0, 1e-15));  // no zz flow
  }
}

TEST_CASE("Mohr-Coulomb uniaxial strengths 2 c cos(phi) / (1 -+ sin phi)", "[materials]") {
  const double sin_phi = std::sin(rad(30.0)), cos_phi = std::cos(rad(30.0));
  for (const bool cutoff : {false, true}) {
    MaterialParameters p = soil(10.0);
    // A cut-off below the uniaxial tensile strength (23.1 kPa) caps tension, and changes
    // nothing in compression.
    if (cutoff) test::mohr_coulomb_of(p).tensile_strength = 10e3;
    const double compressive = 2.0 * test::strength_of(p).cohesion * cos_phi / (1.0 - sin_phi);
    const double tensile = 2.0 * test::strength_of(p).cohesion * cos_phi / (1.0 + sin_phi);

    // sxx = 0 held; syy by strain. szz = nu syy stays intermediate.
    const MaterialPointRun c = run(p, Vec4::Zero(), {segment(100, stress(0.0), strain(-0.01), {})});
    CHECK(c.rows.back().branch == Branch::Plane);
    CHECK_THAT(c.rows.back().stress[kYY], WithinRel(-compressive, kDriverTol));
    CHECK_THAT(c.rows.back().stress[kXX], WithinAbs(0.0, 1e-10 * compressive));

    const MaterialPointRun t = run(p, Vec4::Zero(), {segment(100, stress(0.0), strain(0.01), {})});
    const MaterialPointRow& end = t.rows.back();
    if (cutoff) {
      CHECK(end.branch == Branch::Tension);
      CHECK(end.active_planes == kTension1);
      CHECK_THAT(end.stress[kYY],
                 WithinRel(*test::mohr_coulomb_of(p).tensile_strength, kDriverTol));
    } else {
      CHECK(end.branch == Branch::Plane);
      CHECK_THAT(end.stress[kYY], WithinRel(tensile, kDriverTol));
    }
    CHECK_THAT(end.stress[kXX], WithinAbs(0.0, 1e-10 * tensile));
  }
}

TEST_CASE("Mohr-Coulomb simple shear at zero mean stress with psi = 0 plateaus at c cos(phi)",
          "[materials]") {
  const MaterialParameters p = soil(0.0);
  // Free normal stresses (sxx = syy = 0 held), gxy pushed to 2 %.
  const MaterialPointRun r =
      run(p, Vec4::Zero(), {segment(200, stress(0.0), stress(0.0), strain(0.02))});
  const double tau =
      test::strength_of(p).cohesion * std::cos(rad(test::strength_of(p).friction_angle));
  const MaterialPointRow& end = r.rows.back();
  CHECK(end.branch == Branch::Plane);
  CHECK_THAT(end.stress[kXY], WithinRel(tau, kDriverTol));
  for (const MaterialPointRow& row : r.rows) {
    // psi = 0: no plastic volume change, so szz = nu (sxx + syy) = 0 and the mean stress
    // stays zero (absolute, 1e-10 of the shear strength: the Newton tolerance).
    CHECK_THAT(row.stress[kXX] + row.stress[kYY] + row.stress[kZZ], WithinAbs(0.0, 1e-10 * tau));
    CHECK(row.stress[kXY] <= tau * (1.0 + kDriverTol));
  }
}

TEST_CASE("Mohr-Coulomb apex under hydrostatic tension at c cot(phi)", "[materials]") {
  const MaterialParameters p = soil(10.0);
  // Equal in-plane stretching: szz lags (ezz = 0), so the stress first reaches the left
  // edge (sxx = syy), then runs along it into the apex.
  const MaterialPointRun r = run(p, Vec4::Zero(), {segment(100, strain(0.01), strain(0.01), {})});
  bool saw_edge = false;
  for (const MaterialPointRow& row : r.rows) saw_edge = saw_edge || row.branch == Branch::Edge;
  CHECK(saw_edge);
  const MaterialPointRow& end = r.rows.back();
  CHECK(end.branch == Branch::Apex);
  const double apex =
      test::strength_of(p).cohesion / std::tan(rad(test::strength_of(p).friction_angle));
  // The apex stress is set directly from c, so it is exact to round-off (1e-14).
  CHECK_THAT(end.stress[kXX], WithinRel(apex, 1e-14));
  CHECK_THAT(end.stress[kYY], WithinRel(apex, 1e-14));
  CHECK_THAT(end.stress[kZZ], WithinRel(apex, 1e-14));
  CHECK_THAT(end.stress[kXY], WithinAbs(0.0, 1e-14 * apex));
}

TEST_CASE("Mohr-Coulomb with zero dilation: no return beyond the apex, said so", "[materials]") {
  const MaterialParameters p = soil(0.0);
  // Hydrostatic-ish tension far beyond c cot(phi) = 34.6 kPa in one increment.
  const MaterialResult r = integrate(p, {}, {0.01, 0.01, 0.0});
  CHECK_FALSE(r.status.converged);
  CHECK(r.status.reason.find("dilation") != std::string::npos);
  CHECK(r.status.suggested_fraction == 0.0);
  // With a cut-off below the apex the same step returns to s1 = s2 = T (szz lags).
  MaterialParameters cut = p;
  test::mohr_coulomb_of(cut).tensile_strength = 5e3;
  const MaterialResult t = integrate(cut, {}, {0.01, 0.01, 0.0});
  REQUIRE(t.status.converged);
  CHECK(t.branch == Branch::Tension);
  CHECK_THAT(t.stress[kXX], WithinRel(5e3, 1e-14));
  CHECK_THAT(t.stress[kYY], WithinRel(5e3, 1e-14));
}

TEST_CASE("Mohr-Coulomb oedometric compression runs on the left edge, on both planes",
          "[materials]") {
  // From an isotropic 100 kPa, eyy pushed down with exx = 0: by symmetry sxx = szz (both
  // less compressive than syy), so the trial sits on the edge where the planes (x, y) and
  // (z, y) meet; plastic flow keeps it there. The path reaches yield only if
  // sin(phi) < G / (lambda + G) = 1 - 2 nu, hence nu = 0.2 here (yield at eyy = -1.94 %).
  MaterialParameters p = soil(10.0);
  p.poisson = 0.2;
  const MaterialPointRun r =
      run(p, {-kP0, -kP0, -kP0, 0.0}, {segment(100, strain(0.0), strain(-0.1), strain(0.0))});
  const MohrCoulombAngles a =
      mohr_coulomb_angles(test::strength_of(p).friction_angle, test::strength_of(p).dilation_angle);
  int on_edge = 0;
  for (const MaterialPointRow& row : r.rows) {
    if (row.branch != Branch::Edge) continue;
    ++on_edge;
    CHECK(row.active_planes == (kMain | kLeftEdge));
    const double sx = row.stress[kXX], sy = row.stress[kYY], sz = row.stress[kZZ];
    // Both planes at the cohesion, each written out from the catalogue's criterion;
    // exact to round-off of the return (1e-12 of the stresses).
    const double strength = 2.0 * test::strength_of(p).cohesion * a.cos_phi;
    CHECK_THAT((sx - sy) + (sx + sy) * a.sin_phi, WithinRel(strength, 1e-12 * -sy / strength));
    CHECK_THAT((sz - sy) + (sz + sy) * a.sin_phi, WithinRel(strength, 1e-12 * -sy / strength));
    // The plastic flow of an edge has a zz part: szz is no longer nu (sxx + syy).
    CHECK(std::abs(sz - p.poisson * (sx + sy)) > 1e3);
  }
  CHECK(on_edge > 70);
  CHECK(r.rows.back().branch == Branch::Edge);
}

TEST_CASE("Mohr-Coulomb cohesion softening follows the table", "[materials]") {
  MaterialParameters p = soil(10.0);
  test::strength_of(p).hardening = {{0.0, 20e3}, {0.01, 10e3}, {0.02, 5e3}};
  const MaterialPointRun r = biaxial(p, 400, -0.06);
  const CohesionLaw law(test::strength_of(p).hardening, test::strength_of(p).cohesion);
  const MohrCoulombAngles a =
      mohr_coulomb_angles(test::strength_of(p).friction_angle, test::strength_of(p).dilation_angle);
  const double n = flow_factor(test::strength_of(p).friction_angle);
  int plastic = 0;
  for (const MaterialPointRow& row : r.rows) {
    if (row.branch != Branch::Plane) continue;
    ++plastic;
    // eps_p from the plastic strain, independently of the multipliers it was summed from
    // (fixed axes: eps_p = cos(phi) (e1^p - e3^p)); 1e-12: round-off of the sums.
    const double e = row.state.eps_p;
    CHECK_THAT(
        e, WithinRel(a.cos_phi * (row.state.plastic_strain[kXX] - row.state.plastic_strain[kYY]),
                     1e-12));
    // The table, interpolated by hand.
    double c = 5e3;
    if (e < 0.01)
      c = 20e3 - 10e3 * e / 0.01;
    else if (e < 0.02)
      c = 10e3 - 5e3 * (e - 0.01) / 0.01;
    CHECK_THAT(law.value(e), WithinRel(c, 1e-14));
    // The stress on the softened surface: |syy| = N p0 + 2 c(eps_p) sqrt(N).
    CHECK_THAT(-row.stress[kYY], WithinRel(n * kP0 + 2.0 * c * std::sqrt(n), kDriverTol));
  }
  CHECK(plastic > 300);
  CHECK(r.rows.back().state.eps_p > 0.02);  // past the table's end: c = 5 kPa from there
}

TEST_CASE("Mohr-Coulomb cohesion hardening follows the table", "[materials]") {
  MaterialParameters p = soil(20.0);
  test::strength_of(p).hardening = {{0.0, 20e3}, {0.005, 30e3}, {0.05, 35e3}};
  const MaterialPointRun r = biaxial(p, 200, -0.04);
  const MohrCoulombAngles a =
      mohr_coulomb_angles(test::strength_of(p).friction_angle, test::strength_of(p).dilation_angle);
  const double n = flow_factor(test::strength_of(p).friction_angle);
  int plastic = 0;
  for (const MaterialPointRow& row : r.rows) {
    if (row.branch != Branch::Plane) continue;
    ++plastic;
    const double e = row.state.eps_p;
    double c = 35e3;  // constant beyond the table's end
    if (e < 0.005)
      c = 20e3 + 10e3 * e / 0.005;
    else if (e < 0.05)
      c = 30e3 + 5e3 * (e - 0.005) / 0.045;
    // The cohesion read back from the stress through the criterion.
    const Vec3 s = principal_stress(row.stress).sorted();
    const double c_read = ((s[0] - s[2]) + (s[0] + s[2]) * a.sin_phi) / (2.0 * a.cos_phi);
    CHECK_THAT(c_read, WithinRel(c, kDriverTol * n));
  }
  CHECK(plastic > 100);
  CHECK(r.rows.back().state.eps_p > 0.005);
}
