// The blocks' own force element (solver/force_element.hpp): inertia, elasticity, weight and
// initial stress in the step's system (Shi 1988, ch. 2), with the pseudo-rigid body's
// rotating inertia and the plastic blocks' Newton terms; and what they book in the energy
// account: the elastic strain energy, the backward-Euler and dynamic-coefficient damping, the
// initial stress's and base shaking's work, and the plastic dissipation.
#pragma once

#include "solver/energy_terms.hpp"
#include "solver/force_element.hpp"
#include "solver/world.hpp"

namespace dda {

extern const ForceElement kBlockElement;

// Elastic strain energy of one block (J/m): A/2 e^T D e for elastic blocks; for plastic
// ones A/2 (s - s0) : C^-1 : (s - s0) over (xx, yy, zz, xy), which excludes plastic strain.
double block_strain_energy(const World& world, const Block& b);

// After the configuration update: the plastic blocks' plastic work and the backward-Euler
// share of their stress change, from the state StepEnergy kept from before the step.
void book_plastic_blocks(const World& world, const StepEnergy& step, EnergyLedger& ledger);

}  // namespace dda
