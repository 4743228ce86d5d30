// Reference motion of one pseudo-rigid body (Cohen and Muncaster 1988) by SUNDIALS CVODE:
// a body whose deformation is homogeneous, x = xc + R(theta) U (X - Xc), U = I + E with E
// the strain in the body's own axes. That is exactly a DDA block's kinematics with finite
// rotation, so the solution is an independent reference for one block of any stiffness:
// a spinning block's centrifugal stress, a swinging block's strain
// (docs/rotating-inertia.md).
//
// The equations are Lagrange's, derived here without the step's formulas: kinetic energy
// T = 1/2 m |xc'|^2 + 1/2 tr(F' J0 F'^T) with F = R U and J0 = int rho (X - Xc)(X - Xc)^T dA,
// so T = 1/2 q'^T M(q) q' over q = (xc, yc, theta, e_x, e_y, g_xy) with M from the
// derivatives of F; potential energy V = -m g . xc + A0 W(e) (+ a penalty pin, as in DDA:
// p/2 |x_P - anchor|^2), W the strain energy per initial area: 1/2 e^T D e (linear), or
// 1/2 h^T D h with h the Hencky strain ln U (ElasticLaw::Hencky, see below). Then
// M q'' = -dV/dq - (M' q' - 1/2 d(q'^T M q')/dq), with the derivatives of M taken by
// central differences (M is quadratic in the strain, so they are
// exact but for round-off). CVODE's BDF method with a dense difference-quotient Jacobian
// (the pin and the strain modes are stiff), relative tolerance 1e-10 by default.
// Not part of the library users link (verification/ and tests/ only).
#pragma once

#include <vector>

#include "kinematics/types.hpp"

namespace dda::reference {

// The elastic law of the body. Linear: W = 1/2 e^T D e on the Biot strain e = U - I, the
// small-strain law (D e is then the Biot stress). Hencky: W = 1/2 h^T D h on the Hencky
// strain h = ln U (engineering shear in both), the law the default rotation treatment
// (finite_rotation_polar) gives a block: D h is the Kirchhoff stress in the body's axes,
// tau^ = R^T tau R, tau = det(F) sigma. The force on the strain is then
// -A0 dW/de = -A0 T_B : dU/de, with the Biot stress T_B = L(tau^), L the derivative of the
// matrix logarithm at U (self-adjoint: tau^ : dH = tau^ : L(dU) = L(tau^) : dU). In U's
// principal axes, with stretches l1, l2, L(tau^) has the entries tau^_ii / l_i on the
// diagonal and tau^_12 (ln l1 - ln l2) / (l1 - l2) off it; for an isotropic D, tau^ is
// coaxial with H and T_B = tau^ U^-1. The first Piola stress P = R T_B is work-conjugate to
// F = R U: A0 P : dF = A0 T_B : dU for dF = R dU, and for a turn, dF = dtheta J F,
// P : J F = T_B : J U = 0 when T_B commutes with U (an isotropic law puts no torque on the
// body); the angle equation has no elastic term in either law, since W depends on U alone.
enum class ElasticLaw { Linear, Hencky };

struct PseudoRigidBody {
  double mass = 0.0;             // rho A0 (kg per metre of thickness), > 0
  double area = 0.0;             // A0 (m^2), > 0
  Mat2 inertia = Mat2::Zero();   // J0 about the centroid, material configuration (kg m^2/m)
  Mat3 elastic = Mat3::Zero();   // D on (e_x, e_y, g_xy) or on (h_x, h_y, 2 h_xy)
  ElasticLaw law = ElasticLaw::Linear;
  Vec2 gravity = Vec2::Zero();   // m/s^2
  // An optional penalty pin: the material point at pin_offset (from the centroid, in the
  // initial configuration, where the body's axes are the global ones) is pulled to anchor.
  bool pinned = false;
  Vec2 pin_offset = Vec2::Zero();
  Vec2 anchor = Vec2::Zero();
  double pin_stiffness = 0.0;    // N/m per metre of thickness
};

struct PseudoRigidState {
  double time = 0.0;
  Vec2 centroid = Vec2::Zero();
  double angle = 0.0;              // theta, counter-clockwise (rad)
  Vec3 strain = Vec3::Zero();      // in the body's axes, engineering shear
  Vec2 velocity = Vec2::Zero();
  double omega = 0.0;
  Vec3 strain_rate = Vec3::Zero();
};

struct PseudoRigidOptions {
  double rtol = 1e-10;
  double length_scale = 1.0;   // m: absolute tolerance of positions = rtol x this
  double strain_scale = 1e-4;  // absolute tolerance of strains = rtol x this
  long max_steps = 10000000;
};

// The states at the requested times (s, non-decreasing, >= start.time). Throws
// std::runtime_error naming the CVODE call on a failure, std::invalid_argument on bad input.
std::vector<PseudoRigidState> pseudo_rigid_sample(const PseudoRigidBody& body,
                                                  const PseudoRigidState& start,
                                                  const std::vector<double>& times,
                                                  const PseudoRigidOptions& opt = {});

// The Hencky strain ln U (engineering shear) of the Biot strain e = U - I (U = I + [[e_x,
// g_xy/2], [g_xy/2, e_y]], positive definite), by U's principal axes.
Vec3 hencky_of_biot(const Vec3& biot);

// The elastic energy A0 W(e) (J per metre) and the generalised force -A0 dW/de on
// (e_x, e_y, g_xy) of the body's law at Biot strain e. Exposed for tests.
double pseudo_rigid_elastic_energy(const PseudoRigidBody& body, const Vec3& strain);
Vec3 pseudo_rigid_elastic_force(const PseudoRigidBody& body, const Vec3& strain);

// The body's mass matrix M(q) over (xc, yc, theta, e_x, e_y, g_xy) at strain e (it does not
// depend on the position or the angle). Exposed for tests.
Mat6 pseudo_rigid_mass(const PseudoRigidBody& body, const Vec3& strain);

}  // namespace dda::reference
