// The energy account of a run (J per metre of thickness): what the scene holds, what loads
// did to it and what the step removed, step by step; the unexplained remainder measures
// energy the method created or lost without a cause (docs/energy-balance.md).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "contact/contact.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// What the scene holds at one instant.
struct EnergyTotals {
  double kinetic = 0.0;         // sum of 1/2 v^T M v over free blocks
  double potential = 0.0;       // sum of -m g . xc (zero at the origin)
  double strain_energy = 0.0;   // elastic strain energy (plastic strain excluded)
  double contact_energy = 0.0;  // contact normal and shear springs, pins
  double total() const { return kinetic + potential + strain_energy + contact_energy; }
};

// The terms one accepted step adds to the account (computed with the step's own T and
// the contacts as the open-close loop left them, before the configuration update).
struct StepEnergy {
  double load_work = 0.0;             // point loads and initial stresses on the increments
  double multiplier_work = 0.0;       // the contacts' multiplier forces p s on the normal motion
  double friction_dissipation = 0.0;  // sum over sliding contacts of max(0, -F . slip)
  double damping_dissipation = 0.0;   // implicit springs and strains, dynamic coefficient
  double friction_gain = 0.0;         // sum of max(0, F . slip): friction pushing forward
  // Plastic blocks, before the step: their elastic energy, and their stress (xx, yy, zz,
  // xy) and total strain in the frame their material integrates in (the block frame for
  // the treatments that keep one, else global), for the plastic work.
  std::vector<double> plastic_elastic_before;
  std::vector<Vec4> plastic_stress_before;
  std::vector<Vec3> plastic_strain_before;
  std::vector<double> plastic_area_before;  // m^2
  // The contacts that brought the most energy into the step (what their springs held at its
  // start, plus friction that pushed forward), largest first, at most three: the energy
  // guard names them.
  struct Suspect {
    ContactKey key;
    double energy = 0.0;  // J/m
  };
  std::vector<Suspect> suspects;
};

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

// Elastic strain energy of one block (J/m): A/2 e^T D e for elastic blocks; for plastic
// ones A/2 (s - s0) : C^-1 : (s - s0) over (xx, yy, zz, xy), which excludes plastic strain.
double block_strain_energy(const World& world, const Block& b);

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

// After an accepted step: each contact keeps its shear spring's energy for the next step's
// account (ContactState::spring_energy).
void record_spring_energies(std::vector<Contact>& contacts, double penalty);

}  // namespace dda
