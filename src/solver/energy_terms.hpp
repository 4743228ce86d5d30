// The energy terms one accepted step books and what the scene holds at one instant: the
// plain data each force element fills (solver/force_element.hpp) and the account adds up
// (solver/energy.hpp; docs/energy-balance.md).
#pragma once

#include <vector>

#include "contact/contact.hpp"
#include "kinematics/types.hpp"
#include "materials/voigt4.hpp"

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
  // Yielding bolts' plastic work, and the spring energy of a bolt that breaks (booked with
  // the plastic blocks' plastic dissipation).
  double plastic_work = 0.0;
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

// Records a contact that brought `energy` (J/m) into the step among the step's suspects
// (largest first, at most three) for the energy guard's message (solver/energy.cpp).
void note_suspect(StepEnergy& step, const ContactKey& key, double energy);

}  // namespace dda
