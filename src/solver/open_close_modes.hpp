// Shi's open-close loop (control.contact_solver "open_close", the reference path): after
// each solve, every contact is measured at the answer (its trial), decided by the pure rule
// and policy of contact/open_close_decision.hpp, and then changed, once it is known whether
// the loop goes on. The Newton solver (solver/contact_newton.hpp) decides from the contact's
// response instead and shares only predicted_slip.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact/contact.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// What one pass of the contact decisions found.
struct ContactUpdate {
  int changed = 0;  // contacts that changed mode (0: the open-close loop has converged)
  // Contacts held closed by the chatter rule although the solve puts them in tension beyond
  // the held-tension band: a step that ends with any is not accepted (it is cut), since the
  // held spring pulls its vertex across the gap it started with and so creates energy.
  int held_in_tension = 0;
};

// From the step's increments d: each contact's new gap, forces and next mode.
ContactUpdate update_contact_modes(const World& world, std::vector<Contact>& contacts,
                                   const Eigen::VectorXd& d, const StepContext& ctx);

// Where a contact measures its gap and friction next (ContactState::predicted_slip): a
// sliding contact's slip in the latest solve (iterate.slip), within twice the larger step
// limit of its blocks; zero for any other mode.
double predicted_slip(const World& world, const Contact& c);

}  // namespace dda
