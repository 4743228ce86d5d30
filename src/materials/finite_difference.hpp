// The tangent of integrate() by central finite differences of its stress, the independent
// reference for the consistent tangents (docs/closed-forms.md, "Tangents").
#pragma once

#include "materials/material.hpp"

namespace dda {

// Column j: (s(e + h u_j) - s(e - h u_j)) / 2h of the in-plane stress, all from `start`.
// Truncation error O(h^2 |s'''|), round-off O(eps |s| / h).
Mat3 finite_difference_tangent(const MaterialParameters& params, const MaterialState& start,
                               const Vec3& total_strain, const Vec4& initial_stress, double h);

}  // namespace dda
