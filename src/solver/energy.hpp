// The energy account of a run (J per metre of thickness): what the scene holds, what loads
// did to it and what the step removed, step by step; the unexplained remainder measures
// energy the method created or lost without a cause (docs/energy-balance.md).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "contact/contact.hpp"
#include "solver/elements/block_element.hpp"  // block_strain_energy
#include "solver/energy_terms.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// The strain at which the free blocks' strain energy sets the floor of the energy scale
// (start_energy_account; docs/energy-balance.md, "The energy scale and the guard").
inline constexpr double kRestScaleStrain = 1e-6;

// The energy guard: a message naming the step and the suspect contacts when the
// unexplained gain passes `tolerance` x the scene's energy scale; empty otherwise.
std::string energy_guard_message(const World& world, const StepEnergy& step, double tolerance);
// The same for a loss: a message when the remainder after the last step is below minus
// `tolerance` times the scale (energy gone that no term booked), else empty.
std::string energy_loss_message(const World& world, double tolerance);
// Whether the run's most negative remainder so far lies below minus `tolerance` times the
// scale (summary.json's energy `losses_beyond_tolerance`).
bool energy_lost_beyond(const EnergyLedger& led, double tolerance);

// Energy stored in the contacts' springs after an open-close loop (closed contacts'
// normal springs, penetrating open ones, locked shear springs) and in the pins.
double contact_energy(const World& world, const std::vector<Contact>& contacts,
                      double penalty);

// The scene's energies; the contact term is world.energy.contact_energy, which the step
// records after every accepted solve.
EnergyTotals scene_energy(const World& world);

// The terms of an accepted step (before update_configuration).
StepEnergy step_energy(const World& world, const std::vector<Contact>& contacts,
                       const Eigen::VectorXd& d, const StepContext& ctx);

// After the update: adds the step's terms and the plastic work to world.energy and
// recomputes the remainder against the start.
void commit_step_energy(World& world, const StepEnergy& step, const std::vector<Contact>& contacts,
                        double penalty);

// Starts the account on the world's present state (before the first step).
void start_energy_account(World& world);

}  // namespace dda
