// The Mohr-Coulomb surface and the Rankine tension cut-off as planes in sorted principal
// stress space, s1 >= s2 >= s3, tension positive (de Souza Neto, Peric and Owen 2008,
// section 8.2; docs/closed-forms.md, "Mohr-Coulomb").
//
// Mohr-Coulomb plane (i, j), the major stress i with the minor j:
//   f_ij = (s_i - s_j) + (s_i + s_j) sin(phi) - 2 c cos(phi)
// with the flow (plastic potential the same with psi) (1 + sin psi) e_i - (1 - sin psi) e_j.
// With the order kept, f_13 is the largest of the six; f_12 and f_23 join it on the edges.
// Tension plane i: s_i - T, associated.
#pragma once

#include "kinematics/types.hpp"
#include "materials/principal_planes.hpp"

namespace dda {

// Bits of MaterialResult::active_planes.
enum MohrCoulombPlane : unsigned {
  kMain = 1u << 0,       // f_13
  kRightEdge = 1u << 1,  // f_12, with f_13 on the right edge (s2 = s3 after the return)
  kLeftEdge = 1u << 2,   // f_23, with f_13 on the left edge (s1 = s2)
  kTension1 = 1u << 3,   // s1 = T
  kTension2 = 1u << 4,   // s2 = T
  kTension3 = 1u << 5,   // s3 = T
};
constexpr unsigned kApex = kMain | kRightEdge | kLeftEdge;

struct MohrCoulombAngles {
  double sin_phi = 0.0;
  double cos_phi = 1.0;
  double sin_psi = 0.0;
};
MohrCoulombAngles mohr_coulomb_angles(double friction_deg, double dilation_deg);

// f_13 of sorted principal stresses.
double mohr_coulomb_yield(const Vec3& sorted, double cohesion, const MohrCoulombAngles& a);

// (1 - sin psi) s1 - 2 s2 + (1 + sin psi) s3 of the trial: positive, the main-plane return
// would push s3 above s2 first (right edge); negative, s1 below s2 first (left edge).
double mohr_coulomb_edge_indicator(const Vec3& sorted_trial, const MohrCoulombAngles& a);

// Plane f_ij (i major, j minor; 0-based sorted indices).
PrincipalPlane mohr_coulomb_plane(int i, int j, const MohrCoulombAngles& a);
// Plane s_i = T.
PrincipalPlane tension_plane(int i, double tensile_strength);

// The planes of a MohrCoulombPlane bitmask, in bit order; returns their number.
int planes_of(unsigned mask, const MohrCoulombAngles& a, double tensile_strength,
              PrincipalPlane (&out)[kMaxActivePlanes]);

}  // namespace dda
