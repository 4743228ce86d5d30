#include "materials/return_mohr_coulomb.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "materials/principal.hpp"
#include "materials/principal_planes.hpp"
#include "materials/yield_mohr_coulomb.hpp"

namespace dda {

namespace {

// In-plane principal values closer than this (times the stress scale) use the limit of the
// spin term (principal.hpp): the quotient would keep about 8 digits there.
constexpr double kRepeatedTolerance = 1e-8;

struct Tolerances {
  double stress;      // on yield values and principal order
  double multiplier;  // on plastic multipliers (a strain)
};

bool uses_tension(unsigned mask) { return (mask & (kTension1 | kTension2 | kTension3)) != 0u; }

Branch branch_of(unsigned mask) {
  if (uses_tension(mask)) return Branch::Tension;
  if (mask == kApex) return Branch::Apex;
  return std::popcount(mask) == 2 ? Branch::Edge : Branch::Plane;
}

// The return conditions of one active set's result.
bool admissible(unsigned mask, const PlanesReturn& r, std::span<const PrincipalPlane> planes,
                const MohrCoulombAngles& angles, const CohesionLaw& law,
                const MohrCoulombParameters& p, const Tolerances& tol) {
  if (mask == kApex) {
    // de Souza Neto's apex: only the plastic volume change (sum of h dgamma) must be >= 0.
    double dilation = 0.0;
    for (int k = 0; k < r.multipliers.size(); ++k)
      dilation += planes[k].hardening_weight * r.multipliers[k];
    if (dilation < -tol.multiplier) return false;
  } else {
    for (int k = 0; k < r.multipliers.size(); ++k)
      if (r.multipliers[k] < -tol.multiplier) return false;
  }
  const Vec3& s = r.stress;
  if (s[0] - s[1] < -tol.stress || s[1] - s[2] < -tol.stress) return false;
  if (mohr_coulomb_yield(s, law.value(r.eps_p), angles) > tol.stress) return false;
  if (p.tensile_strength && s[0] - *p.tensile_strength > tol.stress) return false;
  return true;
}

}  // namespace

PlasticReturn return_mohr_coulomb(const MohrCoulombParameters& p, const ElasticModuli& moduli,
                                  const Vec4& trial, double eps_p_start) {
  const Mat4 elastic = elastic_matrix4(moduli);
  const MohrCoulombAngles angles = mohr_coulomb_angles(p.friction_angle, p.dilation_angle);
  const CohesionLaw law(p.hardening, p.cohesion);
  const double tension = p.tensile_strength.value_or(0.0);
  const PrincipalStress principal = principal_stress(trial);
  const Vec3 s = principal.sorted();

  // Stress scale: the trial's largest principal value or the strength, whichever is
  // larger; a floor of 1e-12 E for a material with no stress and no strength.
  const double c_start = law.value(eps_p_start);
  const double scale = std::max({s.cwiseAbs().maxCoeff(), c_start, tension, 1e-12 * moduli.young});
  const Tolerances tol{kDecisionTolerance * scale,
                       kDecisionTolerance * scale / (2.0 * moduli.shear)};

  const bool outside_mc = mohr_coulomb_yield(s, c_start, angles) > tol.stress;
  const bool outside_tension = p.tensile_strength && s[0] - tension > tol.stress;
  if (!outside_mc && !outside_tension) return elastic_return(trial, eps_p_start, elastic);

  Mat3 principal_elastic = Mat3::Constant(moduli.lame);
  principal_elastic.diagonal().array() += 2.0 * moduli.shear;

  // The indicator only orders the two edges: both are tried, so its sign near round-off
  // cannot pick a wrong branch.
  const bool right_first = mohr_coulomb_edge_indicator(s, angles) > 0.0;
  const unsigned first_edge = kMain | (right_first ? kRightEdge : kLeftEdge);
  const unsigned second_edge = kMain | (right_first ? kLeftEdge : kRightEdge);
  const unsigned candidates[] = {kMain,
                                 kTension1,
                                 first_edge,
                                 second_edge,
                                 kMain | kTension1,
                                 kTension1 | kTension2,
                                 kMain | kRightEdge | kTension1,
                                 kMain | kTension1 | kTension2,
                                 kMain | kLeftEdge | kTension1,
                                 kMain | kLeftEdge | kTension2,
                                 kLeftEdge | kTension1 | kTension2,
                                 kTension1 | kTension2 | kTension3,
                                 kApex};
  bool apex_singular = false;
  for (const unsigned mask : candidates) {
    if (uses_tension(mask) && !p.tensile_strength) continue;
    PrincipalPlane planes[kMaxActivePlanes];
    const int n = planes_of(mask, angles, tension, planes);
    const std::span<const PrincipalPlane> active(planes, static_cast<std::size_t>(n));
    const PlanesReturn r = return_to_planes(active, s, principal_elastic, eps_p_start, law);
    if (!r.solved) {
      apex_singular = apex_singular || mask == kApex;
      continue;
    }
    if (!admissible(mask, r, active, angles, law, p, tol)) continue;

    PlasticReturn out;
    const Vec3 abz = principal.unsort(r.stress);
    out.stress = stress_from_principal(abz, principal.angle);
    out.eps_p = r.eps_p;
    out.tangent = isotropic_derivative(principal, abz, principal.unsort(r.derivative),
                                       kRepeatedTolerance * scale) *
                  elastic;
    out.branch = branch_of(mask);
    out.active_planes = mask;
    return out;
  }
  if (apex_singular && angles.sin_psi <= 0.0 && angles.sin_phi > 0.0)
    return failed_return(trial, eps_p_start, elastic,
                         "mohr_coulomb: the trial stress is beyond the apex and the dilation "
                         "angle is 0, so no plastic flow can bring it back (give a dilation "
                         "angle or a tension cut-off)",
                         0.0);
  return failed_return(trial, eps_p_start, elastic,
                       "mohr_coulomb: no return branch satisfies the return conditions "
                       "(cohesion softening too steep for a unique return?)",
                       0.5);
}

}  // namespace dda
