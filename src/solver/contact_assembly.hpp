// Contacts inside the open-close loop: their springs and friction forces in the global
// system (Shi 1988, ch. 4), and after each solve, what each contact does next.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact/contact.hpp"
#include "solver/block_system.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// Normal spring (stiffness p) on closed contacts, shear spring (p / 2.5, Shi's usual ratio)
// on locked ones, Coulomb friction tan(phi) N against the slip on sliding ones.
void add_contact_terms(const World& world, std::vector<Contact>& contacts,
                       const StepContext& ctx, BlockSystem& system);

// From the step's increments d: each contact's new gap, forces and next mode. Returns how
// many contacts changed mode (0 means the open-close loop has converged).
int update_contact_modes(const World& world, std::vector<Contact>& contacts,
                         const Eigen::VectorXd& d, const StepContext& ctx);

// The deepest penetration of any contact after the step (m); 0 if none.
double max_penetration(const std::vector<Contact>& contacts);

}  // namespace dda
