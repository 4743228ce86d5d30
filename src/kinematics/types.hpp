// Plain linear-algebra aliases shared by every room. Units: SI throughout
// (m, s, kg, N, Pa); 2D problems are per metre of thickness.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace dda {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat26 = Eigen::Matrix<double, 2, 6>;

// A polygon is its vertices in order, counter-clockwise, without repeating the first one.
using Polygon = std::vector<Vec2>;

// The z component of the cross product of two plane vectors: twice the signed area of the
// triangle they span (> 0 when b is counter-clockwise of a).
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Index of each of Shi's six block unknowns (Shi 1988; paper Eq. 1).
enum Dof : int { kU0 = 0, kV0 = 1, kR0 = 2, kEx = 3, kEy = 4, kGxy = 5 };

}  // namespace dda
