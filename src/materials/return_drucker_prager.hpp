// Drucker-Prager return map: to the cone, or to the apex when the cone return would take
// the deviator through zero (de Souza Neto, Peric and Owen 2008, section 8.3; verification
// catalogue, "Drucker-Prager").
#pragma once

#include "materials/elastic.hpp"
#include "materials/material_types.hpp"
#include "materials/plastic_return.hpp"

namespace dda {

// Cone: s' = (1 - G dgamma / sqrt(J2_trial)) s'_trial, p = p_trial - K eta_bar dgamma,
//   with sqrt(J2_trial) - G dgamma + eta p - xi c(eps_p_start + xi dgamma) = 0.
// Apex (when sqrt(J2_trial) - G dgamma < 0): s' = 0, p = p_trial - K dev,
//   with eta p = xi c(eps_p_start + xi dev / eta_bar); needs eta > 0 and eta_bar > 0.
// Each equation is solved by Newton on its one unknown (scalar_root.hpp).
PlasticReturn return_drucker_prager(const DruckerPragerParameters& p, const ElasticModuli& moduli,
                                    const Vec4& trial, double eps_p_start);

}  // namespace dda
