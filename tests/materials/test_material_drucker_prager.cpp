// Drucker-Prager closed forms (docs/closed-forms.md, "Drucker-Prager"): the matches to
// Mohr-Coulomb, the cone return formula, the apex, the plane-strain limit load, hardening.
#include <catch2/catch.hpp>

#include "support/material_builders.hpp"
#include <cmath>
#include <numbers>
#include <vector>

#include "materials/material.hpp"
#include "materials/material_point.hpp"
#include "materials/yield_drucker_prager.hpp"
#include "materials/yield_mohr_coulomb.hpp"

using namespace dda;
using test::segment;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180.0; }

// As in test_material_mohr_coulomb.cpp: Newton tolerance 1e-10 on the stress-controlled
// components, amplified at most by N = 3 through the strength.
constexpr double kDriverTol = 1e-9;

MaterialParameters dp_soil(double dilation_deg, DruckerPragerMatch match) {
  MaterialParameters p = test::soil(MaterialModel::DruckerPrager, dilation_deg);
  test::drucker_prager_of(p).match = match;
  return p;
}


}  // namespace

TEST_CASE("Drucker-Prager matches touch Mohr-Coulomb on the catalogue's meridians", "[materials]") {
  // Meridian radii rho = sqrt(2 J2) of Mohr-Coulomb at mean stress p (catalogue):
  // 2 sqrt6 (c cos phi - p sin phi) / (3 -+ sin phi), minus on the compressive meridian
  // (outer cone), plus on the tensile one (inner cone). A stress there is on the cone:
  // f = rho / sqrt2 + eta p - xi c = 0. Round-off of a few flops on numbers ~1e5: 1e-10 Pa.
  const double c = 20e3;
  for (const double phi : {10.0, 30.0, 45.0}) {
    const double s = std::sin(rad(phi)), co = std::cos(rad(phi));
    for (const double p : {-200e3, 0.0, 10e3}) {
      const double rho_c = 2.0 * std::sqrt(6.0) * (c * co - p * s) / (3.0 - s);
      const double rho_t = 2.0 * std::sqrt(6.0) * (c * co - p * s) / (3.0 + s);
      const DruckerPragerCoefficients outer =
          drucker_prager_coefficients(DruckerPragerMatch::Outer, phi, phi);
      const DruckerPragerCoefficients inner =
          drucker_prager_coefficients(DruckerPragerMatch::Inner, phi, phi);
      CHECK_THAT(rho_c / std::sqrt(2.0) + outer.eta * p - outer.xi * c, WithinAbs(0.0, 1e-10));
      CHECK_THAT(rho_t / std::sqrt(2.0) + inner.eta * p - inner.xi * c, WithinAbs(0.0, 1e-10));
      // And the Mohr-Coulomb criterion itself agrees: a triaxial compression stress
      // (s1 = s2 > s3) of radius rho_c is on f_13 = 0.
      const double d = rho_c / std::sqrt(6.0);  // deviator (d, d, -2d) has rho = sqrt6 d
      const Vec3 sorted{p + d, p + d, p - 2.0 * d};
      CHECK_THAT(mohr_coulomb_yield(sorted, c, mohr_coulomb_angles(phi, phi)),
                 WithinAbs(0.0, 1e-10));
    }
    // Every match puts the apex at c cot(phi) (catalogue): xi / eta = cot(phi).
    for (const auto m :
         {DruckerPragerMatch::Outer, DruckerPragerMatch::Inner, DruckerPragerMatch::PlaneStrain}) {
      const DruckerPragerCoefficients k = drucker_prager_coefficients(m, phi, 0.0);
      CHECK_THAT(k.xi / k.eta, WithinRel(1.0 / std::tan(rad(phi)), 1e-14));
      CHECK(k.eta_bar == 0.0);  // psi = 0: no dilation
    }
  }
}

TEST_CASE("Drucker-Prager cone return: the catalogue's closed form", "[materials]") {
  // Perfect plasticity, one increment from zero stress into the cone region:
  // dgamma = f_trial / (G + K eta eta_bar), s' = (1 - G dgamma / sqrt J2_trial) s'_trial,
  // p = p_trial - K eta_bar dgamma.
  for (const auto m :
       {DruckerPragerMatch::Outer, DruckerPragerMatch::Inner, DruckerPragerMatch::PlaneStrain}) {
    for (const double psi : {0.0, 15.0, 30.0}) {
      const MaterialParameters p = dp_soil(psi, m);
      const Vec3 e{1e-3, -3e-3, 2e-3};
      const MaterialResult r = integrate(p, {}, e);
      REQUIRE(r.status.converged);
      CHECK(r.branch == Branch::Cone);

      const double g = p.young / (2.0 * (1.0 + p.poisson));
      const double k = p.young / (3.0 * (1.0 - 2.0 * p.poisson));
      const double lame = k - 2.0 * g / 3.0;
      const double vol = e[0] + e[1];
      const Vec4 trial{lame * vol + 2.0 * g * e[0], lame * vol + 2.0 * g * e[1], lame * vol,
                       g * e[2]};
      const double pt = (trial[0] + trial[1] + trial[2]) / 3.0;
      const Vec4 dev{trial[0] - pt, trial[1] - pt, trial[2] - pt, trial[3]};
      const double q =
          std::sqrt(0.5 * (dev[0] * dev[0] + dev[1] * dev[1] + dev[2] * dev[2]) + dev[3] * dev[3]);
      const DruckerPragerCoefficients dp = drucker_prager_coefficients(m, 30.0, psi);
      const double dgamma =
          (q + dp.eta * pt - dp.xi * test::strength_of(p).cohesion) / (g + k * dp.eta * dp.eta_bar);
      const double factor = 1.0 - g * dgamma / q;
      const double pn = pt - k * dp.eta_bar * dgamma;
      // A handful of flops each way: 1e-12 relative to the stress scale (|trial| ~ 2e5).
      const double tol = 1e-12 * trial.cwiseAbs().maxCoeff();
      for (int i = 0; i < 3; ++i) CHECK_THAT(r.stress[i], WithinAbs(factor * dev[i] + pn, tol));
      CHECK_THAT(r.stress[kXY], WithinAbs(factor * dev[3], tol));
      CHECK_THAT(r.state.eps_p, WithinRel(dp.xi * dgamma, 1e-12));  // d eps_p = xi d gamma
      CHECK_THAT(drucker_prager_yield(r.stress, test::strength_of(p).cohesion, dp),
                 WithinAbs(0.0, tol));
    }
  }
}

TEST_CASE("Drucker-Prager plane-strain match: the Mohr-Coulomb biaxial limit load", "[materials]") {
  // Associated flow: the plane-strain match gives the same plane-strain limit load as
  // Mohr-Coulomb (de Souza Neto et al. 2008, section 6.4.6). Lateral -100 kPa held, eyy to
  // -10 %: at the limit the plastic flow has no zz part, and szz settles (exponentially in
  // the strain) where that holds.
  const MaterialParameters p = dp_soil(30.0, DruckerPragerMatch::PlaneStrain);
  const double p0 = 100e3;
  const std::vector<PathSegment> path = {segment(200, ComponentTarget{Control::Stress, -p0},
                                                 ComponentTarget{Control::Strain, -0.1},
                                                 ComponentTarget{Control::Strain, 0.0})};
  const MaterialPointRun r = run_material_point(p, {-p0, -p0, -2.0 * p.poisson * p0, 0.0}, path);
  REQUIRE(r.ok);
  const double n = (1.0 + std::sin(rad(30.0))) / (1.0 - std::sin(rad(30.0)));
  const MaterialPointRow& end = r.rows.back();
  CHECK(end.branch == Branch::Cone);
  CHECK_THAT(-end.stress[kYY],
             WithinRel(n * p0 + 2.0 * test::strength_of(p).cohesion * std::sqrt(n), kDriverTol));
  // The last increments add no plastic zz strain (1e-12 of the 5e-4 strain increment).
  const MaterialPointRow& before = r.rows[r.rows.size() - 2];
  CHECK_THAT(end.state.plastic_strain[kZZ] - before.state.plastic_strain[kZZ],
             WithinAbs(0.0, 1e-12 * 5e-4));
  // The other matches give other limits (a check that the match matters): for phi = 30
  // the plane-strain cone lies inside the inner one (eta 0.480 < 0.495, xi 0.832 < 0.857),
  // which lies inside the outer one, so the limits order outer > inner > plane strain.
  double limits[2] = {0.0, 0.0};
  for (const int i : {0, 1}) {
    MaterialParameters q = p;
    test::drucker_prager_of(q).match =
        i == 0 ? DruckerPragerMatch::Outer : DruckerPragerMatch::Inner;
    const MaterialPointRun other =
        run_material_point(q, {-p0, -p0, -2.0 * p.poisson * p0, 0.0}, path);
    REQUIRE(other.ok);
    limits[i] = -other.rows.back().stress[kYY];
  }
  CHECK(limits[0] > 1.01 * limits[1]);
  CHECK(limits[1] > 1.01 * -end.stress[kYY]);
}

TEST_CASE("Drucker-Prager apex under hydrostatic tension at xi c / eta", "[materials]") {
  for (const auto m : {DruckerPragerMatch::Outer, DruckerPragerMatch::PlaneStrain}) {
    const MaterialParameters p = dp_soil(10.0, m);
    const std::vector<PathSegment> path = {segment(100, ComponentTarget{Control::Strain, 0.01},
                                                   ComponentTarget{Control::Strain, 0.01},
                                                   ComponentTarget{Control::Strain, 0.0})};
    const MaterialPointRun r = run_material_point(p, Vec4::Zero(), path);
    REQUIRE(r.ok);
    const MaterialPointRow& end = r.rows.back();
    CHECK(end.branch == Branch::Apex);
    const DruckerPragerCoefficients k = drucker_prager_coefficients(m, 30.0, 10.0);
    const double apex = k.xi * test::strength_of(p).cohesion / k.eta;
    CHECK_THAT(apex, WithinRel(test::strength_of(p).cohesion / std::tan(rad(30.0)), 1e-14));
    // Set from c directly: exact to round-off.
    for (int i = 0; i < 3; ++i) CHECK_THAT(end.stress[i], WithinRel(apex, 1e-14));
    CHECK_THAT(end.stress[kXY], WithinAbs(0.0, 1e-14 * apex));
    // d eps_p = (xi / eta_bar) d eps_v^p at the apex.
    const Vec4 ep = end.state.plastic_strain;
    CHECK_THAT(end.state.eps_p, WithinRel(k.xi / k.eta_bar * (ep[kXX] + ep[kYY] + ep[kZZ]), 1e-12));
  }
}

TEST_CASE("Drucker-Prager cohesion softening and hardening follow the table", "[materials]") {
  for (const bool soften : {true, false}) {
    MaterialParameters p = dp_soil(10.0, DruckerPragerMatch::PlaneStrain);
    if (soften)
      test::strength_of(p).hardening = {{0.0, 20e3}, {0.01, 10e3}, {0.02, 5e3}};
    else
      test::strength_of(p).hardening = {{0.0, 20e3}, {0.01, 30e3}};
    const double p0 = 100e3;
    const std::vector<PathSegment> path = {segment(300, ComponentTarget{Control::Stress, -p0},
                                                   ComponentTarget{Control::Strain, -0.08},
                                                   ComponentTarget{Control::Strain, 0.0})};
    const MaterialPointRun r = run_material_point(p, {-p0, -p0, -2.0 * p.poisson * p0, 0.0}, path);
    REQUIRE(r.ok);
    const DruckerPragerCoefficients k =
        drucker_prager_coefficients(test::drucker_prager_of(p).match, 30.0, 10.0);
    int plastic = 0;
    for (const MaterialPointRow& row : r.rows) {
      if (row.branch != Branch::Cone) continue;
      ++plastic;
      const double e = row.state.eps_p;
      double c;
      if (soften)
        c = e < 0.01 ? 20e3 - 1e6 * e : (e < 0.02 ? 10e3 - 5e5 * (e - 0.01) : 5e3);
      else
        c = e < 0.01 ? 20e3 + 1e6 * e : 30e3;
      // The cohesion read back from the stress: (sqrt J2 + eta p) / xi; 1e-12 of the
      // stress scale (~3e5 Pa) over xi c.
      const double c_read =
          (std::sqrt(j2_invariant(row.stress)) + k.eta * mean_stress(row.stress)) / k.xi;
      CHECK_THAT(c_read, WithinAbs(c, 1e-12 * 3e5 / k.xi));
    }
    CHECK(plastic > 250);
    CHECK(r.rows.back().state.eps_p > (soften ? 0.02 : 0.01));  // past the table's end
  }
}
