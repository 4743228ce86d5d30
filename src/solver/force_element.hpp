// A force element: one kind of force on the blocks that owns both its terms in the step's
// system and what it books in the energy account, so that the two are written once, side by
// side (as each constraint in Drake's SAP owns its impulse and its cost). The step's
// assembly (solver/assembly.cpp) and the account (solver/energy.cpp) run the table below in
// its order; a new kind of force is one file in solver/elements/ and one line in the table.
//
// Contacts are the one element outside the table: their modes change within the step, so
// the contact solvers assemble them at every iteration and the factor takes them by rank-one
// updates. Their assembly and their energy live together in solver/contact_assembly.hpp.
#pragma once

#include <Eigen/Dense>
#include <span>

#include "solver/block_system.hpp"
#include "solver/energy_terms.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

struct ForceElement {
  // Adds the element's stiffness and forces for the step to the system.
  void (*assemble)(const World& world, const StepContext& ctx, BlockSystem& system);
  // Books the work and the dissipation of the element's forces over an accepted step's
  // increments d (taken before the configuration update, with the step's own T).
  void (*book_step)(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                    StepEnergy& step);
  // Adds the energy the element's springs hold now to `energy` (J/m); nullptr for an
  // element that stores none. (The blocks' strain energy is the account's own term.)
  void (*add_stored)(const World& world, double penalty, double& energy);
  // An element whose stiffness depends on a mode the step's answer decides (a bolt that
  // yields): its modes at an attempt's start, in the loop's terms; nullptr for none.
  void (*start_modes)(const World& world, LoopTerms& terms);
  // After a solve whose answer is d: the modes follow it; returns how many changed (the
  // block terms are then assembled again and the step solved again); nullptr for none.
  int (*follow_modes)(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                      LoopTerms& terms);
  // An accepted step's change of the element's own state (before the configuration update,
  // with the step's own T and modes); nullptr for an element with none.
  void (*commit)(World& world, const Eigen::VectorXd& d, const StepContext& ctx);
};

// The verbs above over every element of the table.
void start_element_modes(const World& world, LoopTerms& terms);
int follow_element_modes(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                         LoopTerms& terms);
void commit_elements(World& world, const Eigen::VectorXd& d, const StepContext& ctx);

// The elements in the order the step assembles and books them: the blocks' own terms
// (inertia, elasticity, weight, initial stress), pins, point loads and joint water, bolts.
std::span<const ForceElement> force_elements();

}  // namespace dda
