#include "kinematics/rotating_inertia.hpp"

#include "kinematics/block_matrices.hpp"
#include "kinematics/point_maps.hpp"

namespace dda {
namespace {

// A generalised force on the block-frame strains, sym(m), in the step's global strain slots
// of h: it turns like a stress, Q : dE^ = (R Q R^T) : dE_global, and with dE_xy = dg/2 on
// both off-diagonal entries the g slot takes Q_xy once.
void set_strain_slots(Vec6& h, const Mat2& m, double theta) {
  const Mat2 r = rotation_matrix(theta);
  const Mat2 q = r * (0.5 * (m + m.transpose())) * r.transpose();
  h[kEx] = q(0, 0);
  h[kEy] = q(1, 1);
  h[kGxy] = q(0, 1);
}

}  // namespace

Mat2 material_inertia(double density, double sxx, double syy, double sxy) {
  Mat2 j;
  j << sxx, sxy, sxy, syy;
  return density * j;
}

Vec6 rotating_inertia_force(const Mat2& j0, double theta, const Vec3& local_strain,
                            const Spin& spin) {
  const Mat2 quarter = quarter_turn();
  const Mat2 u = Mat2::Identity() + strain_tensor(local_strain);
  const Mat2 rate = strain_tensor(spin.strain_rate);
  const double w = spin.omega;
  // What Shi's mass matrix leaves out of G (header). The step's strain slots are global:
  // Newmark differences the block-frame rate turned to the global frame, R E^' R^T, whose
  // time derivative is R (E^'' + omega (J E^' - E^' J)) R^T. That part of the Coriolis term
  // is therefore already in the step; the rest of 2 omega J E^' is omega (J E^' + E^' J),
  // which for a symmetric 2 x 2 tensor is omega tr(E^') J: only a volumetric rate has it.
  const double volumetric_rate = rate.trace();
  const Mat2 g_h = -w * w * u + w * volumetric_rate * quarter;
  Vec6 h = Vec6::Zero();
  set_strain_slots(h, g_h * j0, theta);
  // The rotation equation's 2 omega tr(E^' J0 U) = omega dI_p/dt, less what the mass
  // matrix's rotation-strain coupling takes from the turning slots, omega tr(E^' (J0 -
  // J J0 J^T)): omega tr(E^') tr(J0) (J0 + J J0 J^T = tr(J0) I in two dimensions).
  h[kR0] = w * volumetric_rate * (u * j0 * u).trace();
  return h;
}

Vec6 spatial_rotating_inertia_force(const Mat2& j0, double theta, const Vec3& local_stretch,
                                    const Spin& spin) {
  const Mat2 quarter = quarter_turn();
  const Mat2 u = Mat2::Identity() + strain_tensor(local_stretch);
  const Mat2 rate = strain_tensor(spin.strain_rate);
  const double w = spin.omega;
  // In the block frame (J commutes with R): L^2 and the present second moment U J0 U.
  const Mat2 l2 = -w * w * Mat2::Identity() + w * rate.trace() * quarter + rate * rate;
  const Mat2 l2i = l2 * (u * j0 * u);
  Vec6 h = Vec6::Zero();
  set_strain_slots(h, l2i, theta);
  h[kR0] = (quarter.transpose() * l2i).trace();
  return h;
}

}  // namespace dda
