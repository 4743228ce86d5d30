// Shi's displacement matrix T and the block sub-matrices built from it (Shi 1988;
// paper Eqs. 2-3). Every block uses its current centroid as the reference point (x0, y0),
// so first moments vanish. Pure functions over plain data.
#pragma once

#include "kinematics/polygon.hpp"
#include "kinematics/types.hpp"

namespace dda {

// T as a function linear in the offset (X, Y) = (x - x0, y - y0) from the reference point:
//   T(X, Y) = constant + X * dx + Y * dy.
// Keeping the three coefficient matrices (rather than T at a point) lets integrals of
// T^T T be taken exactly from the polygon moments, and lets later issues swap the
// rotation column (secant rotation) without touching the integrals.
struct LinearT {
  Mat26 constant = Mat26::Zero();
  Mat26 dx = Mat26::Zero();
  Mat26 dy = Mat26::Zero();

  Mat26 at(const Vec2& offset) const { return constant + offset.x() * dx + offset.y() * dy; }
};

// Shi's first-order T (paper Eq. 3):
//   u = u0 - Y r0 + X ex + Y gxy / 2
//   v = v0 + X r0 + Y ey + X gxy / 2
const LinearT& shi_t();

// T with the rotation column a * (X, Y) in place of Shi's (-Y, X) (which is a = J, the
// quarter turn). Used with the columns below; every other column is Shi's.
LinearT t_with_rotation_column(const Mat2& a);

// The rotation column a of a T made by t_with_rotation_column(a) (J for Shi's).
Mat2 rotation_column(const LinearT& t);

// The quarter turn J = [[0, -1], [1, 0]]: Shi's first-order rotation column.
Mat2 quarter_turn();

// The secant column (R(r) - I) / r: with it, T d moves every point by the exact rotation
// through d_r0 = r (R(r) the counter-clockwise rotation matrix). Tends to J as r -> 0 and is
// exactly J at r = 0. finite_rotation iterates r to the step's own r0 (docs/paper-errata.md, item 6).
Mat2 secant_rotation_column(double r);

// Cheng and Zhang's column (R(r) - I) / sin r (paper Eqs. 9-11): with sin r0 as the unknown,
// T' d' is the finite-rotation displacement (paper Eq. 8) when r is the step's own r0;
// sin_variable takes r from the last step. Needs |r| < pi/2.
Mat2 sine_rotation_column(double r);

// Mass matrix int rho T^T T dA over the block (moments about the reference point).
Mat6 mass_matrix(const LinearT& t, const Moments& m, double density);

// Elastic stiffness: strain energy (area/2) e^T D e gives area * D on (ex, ey, gxy).
Mat6 elastic_stiffness(const Moments& m, const Mat3& d);

// Body force int rho T^T g dA. With the centroid as reference only the constant part remains.
Vec6 body_force(const LinearT& t, const Moments& m, double density, const Vec2& g);

// The stress already in the block acts against further strain: -area * s on (ex, ey, gxy).
Vec6 initial_stress_force(const Moments& m, const Vec3& stress);

// A force f at a point of the block: T^T f.
Vec6 point_force(const Mat26& t_at_point, const Vec2& f);

// A penalty spring of stiffness p pulling a material point (where T is t_at_point) towards
// its anchor, `gap` = anchor - current position: stiffness p T^T T, force p T^T gap.
Mat6 spring_stiffness(const Mat26& t_at_point, double p);
Vec6 spring_force(const Mat26& t_at_point, double p, const Vec2& gap);

}  // namespace dda
