// Stage "detect contacts": broad phase over the free blocks' boxes, narrow phase per close
// pair, then the state each contact carried from the last step (mode, anchor, bond).
#pragma once

#include <vector>

#include "contact/contact.hpp"
#include "solver/world.hpp"

namespace dda {

// Replaces `contacts` by the contacts of the world's present configuration. Contacts that
// existed last step (same vertex and edge) keep their state; new ones start locked when
// already closed (gap <= 0) and open otherwise. On the first step (world.step == 0), closed
// contacts whose joint has cohesion or tensile strength start bonded.
void detect_contacts(const World& world, std::vector<Contact>& contacts);

}  // namespace dda
