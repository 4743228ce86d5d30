// The Drucker-Prager cone f = sqrt(J2) + eta p - xi c(eps_p) with the plastic potential
// sqrt(J2) + eta_bar p, p = tr(s) / 3, tension positive (de Souza Neto, Peric and Owen 2008,
// section 6.4.6; docs/closed-forms.md, "Drucker-Prager").
#pragma once

#include "materials/material_types.hpp"
#include "materials/voigt4.hpp"

namespace dda {

struct DruckerPragerCoefficients {
  double eta = 0.0;
  double xi = 0.0;
  double eta_bar = 0.0;  // eta of the dilation angle: associated when dilation = friction
};

// Match to Mohr-Coulomb (phi, c), the dilation angle psi giving eta_bar by the same formula:
//   outer (the cone through the compressive meridians):  eta = 6 sin phi / (sqrt3 (3 - sin phi)),
//                                                        xi = 6 cos phi / (sqrt3 (3 - sin phi));
//   inner (through the tensile meridians): the same with 3 + sin phi;
//   plane strain (the same plane-strain limit load with associated flow):
//     eta = 3 tan phi / sqrt(9 + 12 tan^2 phi), xi = 3 / sqrt(9 + 12 tan^2 phi).
DruckerPragerCoefficients drucker_prager_coefficients(DruckerPragerMatch match, double friction_deg,
                                                      double dilation_deg);

double drucker_prager_yield(const Vec4& s, double cohesion, const DruckerPragerCoefficients& k);

// The flow direction d(potential)/ds as a strain (engineering shear):
// s' / (2 sqrt J2) + eta_bar / 3 1. Undefined at sqrt J2 = 0 (the apex).
Vec4 drucker_prager_flow(const Vec4& s, const DruckerPragerCoefficients& k);

}  // namespace dda
