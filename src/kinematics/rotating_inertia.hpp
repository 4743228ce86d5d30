// The inertia a DDA block's strain unknowns feel in the block's rotating frame
// (docs/rotating-inertia.md has the derivation).
//
// A block's kinematics are affine: x = xc + R(theta) U (X - Xc), U = I + E^ with E^ the
// total strain in the block frame (the local-frame treatments keep exactly this). Its
// acceleration is xc'' + R G (X - Xc) with
//   G = (alpha J - omega^2 I) U + 2 omega J E^' + E^''      (J the quarter turn)
// Shi's mass matrix, built from T on the current geometry, carries the terms linear in the
// accelerations (alpha J U and E^''). The terms quadratic in the velocities are missing from
// every DDA code: the centripetal -omega^2 U (which stretches a spinning block) and the
// Coriolis 2 omega J E^' (with the rate of change of the polar moment it brings to the
// rotation equation). By virtual work over the block (J0 = int rho (X - Xc)(X - Xc)^T dA in
// the material configuration) they are the generalised force
//   on the strains (block frame):  sym(G_h J0),  G_h = -omega^2 U + 2 omega J E^'
//   on the rotation:               2 omega tr(E^' J0 U)   (= omega d/dt tr(U J0 U))
// which the step moves to its right-hand side. A block spinning steadily at omega then
// carries sigma = omega^2 J0 / A in its own axes, whatever its stiffness (to first order in
// the strain), as a body spinning in the plane must.
#pragma once

#include "kinematics/types.hpp"

namespace dda {

// The block's rotational state at which the quadratic terms are taken.
struct Spin {
  double omega = 0.0;                   // angular velocity (rad/s, counter-clockwise)
  Vec3 strain_rate = Vec3::Zero();      // block-frame rate [e^x', e^y', g^xy'] (1/s)
};

// J0: rho times the second moments of the initial polygon about its centroid
// [[int X^2, int XY], [int XY, int Y^2]] (kg m^2 per metre of thickness).
Mat2 material_inertia(double density, double sxx, double syy, double sxy);

// The generalised inertial force of the quadratic velocity terms, in the step's unknowns
// (u0, v0, r0, ex, ey, gxy) with the strain slots in the global frame: the step equations
// hold M a + h + K d = f, so the caller subtracts it from f. `theta` is the block frame's
// angle, `local_strain` E^ = [e^x, e^y, g^xy] (engineering shear), `j0` from
// material_inertia. Translation slots are zero (the centroid's motion has no such terms).
Vec6 rotating_inertia_force(const Mat2& j0, double theta, const Vec3& local_strain,
                            const Spin& spin);

// The same for a block whose step moves its present shape, F' = (I + r0 a + dE) F
// (finite_rotation_polar, docs/large-strain.md): its unknowns are rates of the spatial
// velocity gradient L = omega J + D (D symmetric, global frame), so every point moves at
// xc' + L y, y = x - xc, and accelerates at xc'' + (L' + L^2) y. Shi's mass matrix on the
// present shape, int rho T^T T, acts on L'; the quadratic part
//   L^2 = -omega^2 I + omega tr(D) J + D^2          (J D + D J = tr(D) J in two dimensions)
// is what it leaves out. By virtual work over the present shape, with I_c = int rho y y^T =
// R U J0 U R^T the present second moment, it is the generalised force
//   on the strains (global frame):  sym(L^2 I_c)
//   on the rotation:                tr(J^T L^2 I_c)
// Here `local_stretch` is U - I in the block frame and spin.strain_rate is D turned into the
// block frame (R^T D R). At small strain it is rotating_inertia_force but for terms of order
// the strain (U J0 against U J0 U) and D^2: at strains of per cents those are per cents of
// the centrifugal load (docs/rotating-inertia.md, "Large strain").
Vec6 spatial_rotating_inertia_force(const Mat2& j0, double theta, const Vec3& local_stretch,
                                    const Spin& spin);

}  // namespace dda
