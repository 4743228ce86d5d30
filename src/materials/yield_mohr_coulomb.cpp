#include "materials/yield_mohr_coulomb.hpp"

#include <cmath>
#include <numbers>

namespace dda {

MohrCoulombAngles mohr_coulomb_angles(double friction_deg, double dilation_deg) {
  const double to_rad = std::numbers::pi / 180.0;
  MohrCoulombAngles a;
  a.sin_phi = std::sin(friction_deg * to_rad);
  a.cos_phi = std::cos(friction_deg * to_rad);
  a.sin_psi = std::sin(dilation_deg * to_rad);
  return a;
}

double mohr_coulomb_yield(const Vec3& s, double cohesion, const MohrCoulombAngles& a) {
  return (s[0] - s[2]) + (s[0] + s[2]) * a.sin_phi - 2.0 * cohesion * a.cos_phi;
}

double mohr_coulomb_edge_indicator(const Vec3& s, const MohrCoulombAngles& a) {
  return (1.0 - a.sin_psi) * s[0] - 2.0 * s[1] + (1.0 + a.sin_psi) * s[2];
}

PrincipalPlane mohr_coulomb_plane(int i, int j, const MohrCoulombAngles& a) {
  PrincipalPlane p;
  p.normal[i] = 1.0 + a.sin_phi;
  p.normal[j] = -(1.0 - a.sin_phi);
  p.flow[i] = 1.0 + a.sin_psi;
  p.flow[j] = -(1.0 - a.sin_psi);
  p.cohesion_factor = 2.0 * a.cos_phi;
  // d eps_p = 2 cos(phi) d gamma: eps_p is conjugate to c (material.hpp).
  p.hardening_weight = 2.0 * a.cos_phi;
  return p;
}

PrincipalPlane tension_plane(int i, double tensile_strength) {
  PrincipalPlane p;
  p.normal[i] = 1.0;
  p.flow[i] = 1.0;
  p.constant = tensile_strength;
  return p;
}

int planes_of(unsigned mask, const MohrCoulombAngles& a, double tensile_strength,
              PrincipalPlane (&out)[kMaxActivePlanes]) {
  int n = 0;
  auto add = [&](const PrincipalPlane& p) {
    if (n < kMaxActivePlanes) out[n] = p;
    ++n;
  };
  if (mask & kMain) add(mohr_coulomb_plane(0, 2, a));
  if (mask & kRightEdge) add(mohr_coulomb_plane(0, 1, a));
  if (mask & kLeftEdge) add(mohr_coulomb_plane(1, 2, a));
  if (mask & kTension1) add(tension_plane(0, tensile_strength));
  if (mask & kTension2) add(tension_plane(1, tensile_strength));
  if (mask & kTension3) add(tension_plane(2, tensile_strength));
  return n;
}

}  // namespace dda
