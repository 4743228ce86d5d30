#include "contact/carry_over.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>

namespace dda {
namespace {

struct KeyHash {
  std::size_t operator()(const ContactKey& k) const {
    std::size_t h = static_cast<std::size_t>(k.vertex_block);
    for (int v : {k.vertex, k.edge_block, k.edge}) h = h * 1000003u ^ static_cast<std::size_t>(v);
    return h;
  }
};

// Two blocks whose corners coincide (a mesh of blocks: every shared edge ends in such a
// pair) are held there by one vertex-to-vertex contact, resolved to an edge at either corner
// by which of them lies farther out: a matter of round-off, so from one step to the next the
// contact may come back as the other block's corner on this block's edge, or on the other
// edge at the same corner, under a new key. A bond is a property of the two coincident
// material points, not of the key: a bonded contact that is not found again by key hands its
// bond to a new contact of the same pair at the same corner (the new vertex within a quarter
// of the shorter edge of the old vertex, and the new edge ending there). A locked one stays
// locked, its shear spring anchored at that end of the new edge: the partner's corner, the
// material point the old spring's anchor coincided with when it sat at its own edge's end,
// so the spring keeps the slip it had. Without this a bonded mesh came apart as it deformed
// (verification/footing: half the bonds of a layer of triangles lost in 20 steps).
void hand_over_bonds(const std::vector<Contact>& previous, const std::vector<char>& carried,
                     const std::vector<Contact*>& unmatched) {
  if (unmatched.empty()) return;
  std::unordered_multimap<std::uint64_t, std::size_t> lost;  // by block pair
  auto pair_of = [](const ContactKey& k) { return pair_key(k.vertex_block, k.edge_block); };
  for (std::size_t i = 0; i < previous.size(); ++i) {
    const ContactState& s = previous[i].state;
    if (!carried[i] && s.bonded && s.mode != ContactMode::Open) lost.emplace(pair_of(previous[i].key), i);
  }
  if (lost.empty()) return;
  std::vector<char> taken(previous.size(), 0);
  for (Contact* c : unmatched) {
    const double edge = (c->edge_end - c->edge_start).norm();
    const bool at_start = c->t < 0.5;
    const Vec2 corner = at_start ? c->edge_start : c->edge_end;
    const auto range = lost.equal_range(pair_of(c->key));
    for (auto it = range.first; it != range.second; ++it) {
      const Contact& old = previous[it->second];
      if (taken[it->second]) continue;
      const double tol = 0.25 * std::min(edge, (old.edge_end - old.edge_start).norm());
      if ((c->vertex - corner).norm() > tol || (c->vertex - old.vertex).norm() > tol) continue;
      taken[it->second] = 1;
      ContactState& s = c->state;
      s = ContactState{};
      s.slip_sum = old.state.slip_sum;  // the joint's weakening goes with it
      s.bonded = true;
      s.mode = ContactMode::Lock;
      s.normal_force = old.state.normal_force;
      const bool old_at_end = old.state.mode == ContactMode::Lock &&
                              (std::abs(old.state.t_lock) <= 1e-3 || std::abs(old.state.t_lock - 1.0) <= 1e-3);
      s.t_lock = old_at_end ? (at_start ? 0.0 : 1.0) : c->t;
      break;
    }
  }
}

}  // namespace

void carry_over(const std::vector<Contact>& previous, std::vector<Contact>& found, double touching,
                bool bond_new_closed, const std::vector<JointLaw>& laws) {
  // Detection lists the contacts in the same order every step (block pairs in increasing
  // order, each pair's in a fixed order) and most contacts persist, so a contact's
  // predecessor is most often the one after the last predecessor found: it is looked for
  // there first, and only then in a hash map (made when first needed; making it for every
  // call cost a 1000-brick wall 0.3 ms a step). The keys in `previous` are unique, so both
  // ways find the same predecessor.
  std::unordered_map<ContactKey, const Contact*, KeyHash> by_key;
  std::size_t next = 0;  // where the next predecessor is expected in `previous`
  const auto predecessor = [&](const ContactKey& key) -> const Contact* {
    if (next < previous.size() && previous[next].key == key) return &previous[next++];
    if (by_key.empty()) {
      by_key.reserve(previous.size());
      for (const Contact& c : previous) by_key.emplace(c.key, &c);
    }
    const auto it = by_key.find(key);
    if (it == by_key.end()) return nullptr;
    next = static_cast<std::size_t>(it->second - previous.data()) + 1;
    return it->second;
  };
  std::vector<char> carried(previous.size(), 0);  // previous contacts found again by key
  std::vector<Contact*> unmatched;                 // found contacts without a predecessor
  for (Contact& c : found) {
    if (const Contact* old = predecessor(c.key)) {
      carried[static_cast<std::size_t>(old - previous.data())] = 1;
      // The whole carried state; its predicted slip is the last step's slip, if sliding.
      c.state = old->state;
      ContactState& s = c.state;
      if (s.deferred) {
        // The change the last step left for this one (ContactState::deferred), made now.
        s.mode = s.deferred->mode;
        s.slide_sign = s.deferred->slide_sign;
        if (s.deferred->relock) {
          const double offset = s.deferred->lock_offset;
          s.t_lock = offset != 0.0 ? c.t_behind(offset) : c.t;
        }
        if (s.mode != ContactMode::Slide) s.predicted_slip = 0.0;
        if (s.mode == ContactMode::Open) s.normal_force = 0.0;
        s.deferred.reset();
      }
    } else {
      unmatched.push_back(&c);
      if (c.gap <= touching) {
        c.state.mode = ContactMode::Lock;
        c.state.t_lock = c.t;
        const JointLaw law = contact_joint_law(laws, c);
        c.state.bonded = bond_new_closed && (law.cohesion > 0.0 || law.tensile_strength > 0.0) &&
                         c.length > 0.0;  // a contact of no length has no strength to bond
      }
    }
  }
  hand_over_bonds(previous, carried, unmatched);
}

}  // namespace dda
