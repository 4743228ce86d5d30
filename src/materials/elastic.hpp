// Linear isotropic elasticity in 2D, Voigt order (xx, yy, xy) with engineering shear
// strain gxy = 2 exy. Tension positive.
#pragma once

#include "kinematics/types.hpp"
#include "materials/voigt4.hpp"

namespace dda {

// Plane strain: ezz = 0 (szz = nu (sxx + syy)). Plane stress: szz = 0.
enum class PlaneMode { Strain, Stress };

// The 3x3 matrix D with s = D e. Requires young > 0 and -1 < poisson < 0.5 (checked at input).
Mat3 elastic_matrix(double young, double poisson, PlaneMode plane);

// Shear modulus G, bulk modulus K and Lame's lambda of (young, poisson), and young itself
// (the returns' floor of a stress scale).
struct ElasticModuli {
  double young = 0.0;
  double shear = 0.0;
  double bulk = 0.0;
  double lame = 0.0;
};
ElasticModuli elastic_moduli(double young, double poisson);

// The 4x4 isotropic matrix on (xx, yy, zz, xy) (voigt4.hpp): s = D e with engineering shear.
// Its in-plane rows and columns are elastic_matrix(young, poisson, PlaneMode::Strain).
Mat4 elastic_matrix4(const ElasticModuli& m);

// The strain e = D^-1 s of a 4-component stress (engineering shear out).
Vec4 elastic_compliance4(const ElasticModuli& m, const Vec4& s);

}  // namespace dda
