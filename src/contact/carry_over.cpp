#include "contact/carry_over.hpp"

#include <cstddef>
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
  for (Contact& c : found) {
    if (const Contact* old = predecessor(c.key)) {
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
    } else if (c.gap <= touching) {
      c.state.mode = ContactMode::Lock;
      c.state.t_lock = c.t;
      const JointLaw& law = laws[static_cast<std::size_t>(c.joint)];
      c.state.bonded = bond_new_closed && (law.cohesion > 0.0 || law.tensile_strength > 0.0);
    }
  }
}

}  // namespace dda
