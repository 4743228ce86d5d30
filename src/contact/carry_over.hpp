// What a contact carries from one step to the next: the contacts found on the new
// configuration take the state (mode, slip direction, shear anchor, bond, normal force,
// expected slip) of the contact with the same vertex and edge last step. Pure function.
#pragma once

#include <vector>

#include "contact/contact.hpp"
#include "contact/joint_law.hpp"

namespace dda {

// `found` holds this step's contacts with fresh geometry and default state. Each takes its
// predecessor's state from `previous`, with the change of mode the predecessor deferred (if
// any) made now, a new lock anchored where the vertex now is; a new contact already closed
// (gap <= `touching`: blocks placed face to face keep a few ulps of gap) starts locked,
// anchored where it is, and bonded when `bond_new_closed` (the first step) and its joint law
// has cohesion or tensile strength. The keys in `previous` are unique (detection finds one
// contact per vertex and edge).
void carry_over(const std::vector<Contact>& previous, std::vector<Contact>& found, double touching,
                bool bond_new_closed, const std::vector<JointLaw>& laws);

}  // namespace dda
