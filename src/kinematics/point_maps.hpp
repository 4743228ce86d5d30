// How a block carries its points: over one step from the step's increments (paper Eqs. 2
// and 8), or from the initial configuration by the block's total state in its own frame
// (paper Eq. 19, consistent and as printed). Pure functions over plain data; angles are
// counter-clockwise, as r0 in T (kinematics/frames.hpp).
#pragma once

#include "kinematics/types.hpp"

namespace dda {

// The symmetric strain tensor [[ex, gxy/2], [gxy/2, ey]] of [ex, ey, gxy].
Mat2 strain_tensor(const Vec3& e);

// Rotation by `angle` counter-clockwise.
Mat2 rotation_matrix(double angle);

// Displacement over a step of the point at `offset` = x - x0 from the reference point, with
// the step's increments db = (u0, v0, r0, ex, ey, gxy), paper Eq. (8):
//   u = u0 + X (cos r0 - 1) - Y sin r0 + X ex + Y gxy/2
//   v = v0 + X sin r0 + Y (cos r0 - 1) + Y ey + X gxy/2
// second_order: cos r0 - 1 = -r0^2/2, sin r0 = r0 (MacLaughlin and Sitar); a pure rotation
//   then scales areas by (1 - r0^2/2)^2 + r0^2 = 1 + r0^4/4.
// finite_rotation: the exact cos r0 and sin r0 (Ke; Koo and Chern); a pure rotation is rigid.
Vec2 second_order_displacement(const Vec2& offset, const Vec6& db);
Vec2 finite_rotation_displacement(const Vec2& offset, const Vec6& db);

// The linear part A of a block's map from its initial to its current configuration,
// x = xc + A (X - Xc) (X a material point at the start, Xc the initial reference point, xc
// the current one), from the total rotation r and the total strain e^ in the block's frame:
// frame_map: the block stretched in its own frame, then turned (paper Eq. 19 in the
//   kinematically consistent form): A = R(r) (I + E^).
// frame_map_as_printed: Eq. (19) as printed, the global total strain on the initial offsets:
//   A = R(r) + R E^ R^T. Equal to frame_map only while r is small (docs/paper-errata.md, item 2).
Mat2 frame_map(double r, const Vec3& local_strain);
Mat2 frame_map_as_printed(double r, const Vec3& local_strain);

// The polar decomposition of a 2x2 map with positive determinant, F = R(angle) U, U
// symmetric positive definite. `angle` is the branch nearest `near` (continuous with it);
// `strain` is U - I as [e^x, e^y, g^xy] (Biot strain, engineering shear g^xy = 2 U_xy).
struct PolarDecomposition {
  double angle = 0.0;
  Vec3 strain = Vec3::Zero();
};
PolarDecomposition polar_decomposition(const Mat2& f, double near);

// The Hencky (logarithmic) strain ln U of the stretch U = I + E (E the Biot strain), and
// back, both as [ex, ey, gxy] (engineering shear). A symmetric 2x2 matrix S with eigenvalues
// m +- q (m its mean diagonal, q = sqrt(((Sxx - Syy)/2)^2 + Sxy^2)) has
//   ln S = (ln(m^2 - q^2) / 2) I + (atanh(q/m) / q) (S - m I)      (S positive definite),
//   exp S = e^m (cosh(q) I + (sinh(q) / q) (S - m I)),
// the scalar factors taken by their series where q is small (no 0/0).
Vec3 hencky_from_stretch(const Vec3& biot);
Vec3 stretch_from_hencky(const Vec3& hencky);

// finite_rotation_polar's map from the initial configuration: A = R(r) exp(H), H the
// block-frame Hencky strain.
Mat2 hencky_frame_map(double r, const Vec3& hencky);

}  // namespace dda
