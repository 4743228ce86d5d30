// Linear isotropic elasticity in 2D, Voigt order (xx, yy, xy) with engineering shear
// strain gxy = 2 exy. Tension positive.
#pragma once

#include "kinematics/types.hpp"

namespace dda {

// Plane strain: ezz = 0 (szz = nu (sxx + syy)). Plane stress: szz = 0.
enum class PlaneMode { Strain, Stress };

// The 3x3 matrix D with s = D e. Requires young > 0 and -1 < poisson < 0.5 (checked at input).
Mat3 elastic_matrix(double young, double poisson, PlaneMode plane);

}  // namespace dda
