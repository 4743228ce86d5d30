// Bonds formed at a stage's start (docs/scene-format.md, "stages", bond_closed_contacts): a
// pure rule over the contacts and the joint laws, so that a slope consolidated statically
// gets its cohesive bonds on the contacts closed at the end of the consolidation.
#pragma once

#include <vector>

#include "contact/contact.hpp"
#include "contact/joint_law.hpp"

namespace dda {

// Every closed contact (mode not Open) whose joint law has cohesion or tensile strength
// becomes bonded, a bond broken earlier included (a new bond forms). `laws` is indexed by
// Contact::joint. Returns how many bonds were formed (contacts already bonded not counted).
//
// A bonded contact is held locked (joint_law.hpp), so a sliding one is locked here, with its
// shear spring anchored where its vertex now is: the slip of its last step carried to the
// edge parameter, t + slip / edge length (first order in the step's rotation, like the
// contact's own measures), so the new spring starts unstretched. A locked contact keeps its
// anchor, and so the shear force its spring carries.
int bond_closed_contacts(std::vector<Contact>& contacts, const std::vector<JointLaw>& laws);

}  // namespace dda
