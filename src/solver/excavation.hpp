// Excavation: a stage that removes blocks at its start (StageSpec::excavate), as a cut slope
// is benched down lift by lift. A removed block stays in the world's list (every index, and
// history.csv's rows, stay as they were) but is fixed, touches nothing and counts in no
// energy term; its contacts go with it, a bolt with an end in it breaks, and the free blocks'
// unknowns are numbered again. What the removal takes out of the scene (the block's kinetic,
// potential and strain energy, its contacts' and bolts' spring energy) is booked as the
// energy account's `excavation`, so that the balance holds across it.
#pragma once

#include <vector>

#include "contact/contact.hpp"

namespace dda {

struct World;

// Removes blocks `indices` (not yet excavated) from the world and their contacts from
// `contacts`. Returns how many it removed.
int excavate_blocks(World& world, std::vector<Contact>& contacts, const std::vector<int>& indices);

// Whether any stage of the world excavates (the outputs then say which blocks are gone).
bool world_excavates(const World& world);

}  // namespace dda
