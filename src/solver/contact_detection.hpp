// Stage "detect contacts": broad phase over the free blocks' boxes, narrow phase per close
// pair, then the state each contact carried from the last step (mode, anchor, bond).
// Two paths give the same contacts bit for bit: the simple one, which sweeps every box and
// keeps nothing, and the one the step loop uses, which carries the broad phase's pair list
// and its buffers from step to step (DetectionCache).
#pragma once

#include <utility>
#include <vector>

#include "contact/carried_pairs.hpp"
#include "contact/contact.hpp"
#include "contact/narrow_phase.hpp"
#include "solver/world.hpp"

namespace dda {

// What detection keeps between calls. Only `pairs` is carried state, and it is checked
// against the present boxes on every call (contact/carried_pairs.hpp), so any world may be
// passed with any cache; the rest are buffers rebuilt on every call, kept to avoid
// reallocations.
struct DetectionCache {
  CarriedPairs pairs;
  std::vector<Box> boxes;
  std::vector<std::pair<int, int>> close;  // pairs whose boxes overlap now
  std::vector<PolygonFeatures> features;   // per block
  std::vector<ContactCandidate> candidates;
  std::vector<Contact> found;
};

// The extra margin of the carried pair list, as a share of the search distance: the boxes
// the list is made from are grown by this much more than the present ones (the largest
// pair's search distance, World::search_distance). A step moves a vertex at most its block's
// step limit, at most 1/2.5 of that, so a block moving at its limit leaves its grown box every
// 2 or 3 steps (and is swept again), a settling or settled one stays in it; the larger boxes pair few more blocks (in the brick walls none:
// bricks two rows apart are 0.5 m apart, the grown boxes reach 3.75 cm).
inline constexpr double kCarriedPairMargin = 1.0;

// Replaces `contacts` by the contacts of the world's present configuration. Contacts that
// existed last step (same vertex and edge) keep their state; new ones start locked when
// already closed (gap <= 0) and open otherwise. On the first step (world.step == 0), closed
// contacts whose joint has cohesion or tensile strength start bonded.
void detect_contacts(const World& world, std::vector<Contact>& contacts, DetectionCache& cache);

// The same with nothing carried (a cache of its own).
void detect_contacts(const World& world, std::vector<Contact>& contacts);

// The simple path, kept as the reference the carried one is tested against: a new sweep of
// every box, the narrow phase on every close pair, nothing kept. Same result.
void detect_contacts_full(const World& world, std::vector<Contact>& contacts);

}  // namespace dda
