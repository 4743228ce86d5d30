// Scene energy totals (J per metre of thickness), for the history and for conservation tests.
#pragma once

#include "solver/world.hpp"

namespace dda {

struct EnergyTotals {
  double kinetic = 0.0;        // sum of 1/2 v^T M v over free blocks
  double potential = 0.0;      // sum of -m g . xc (zero at the origin)
  double strain_energy = 0.0;  // sum of area/2 e^T D e (elastic strain since the start)
};

EnergyTotals scene_energy(const World& world);

}  // namespace dda
