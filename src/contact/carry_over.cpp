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
  std::unordered_map<ContactKey, const Contact*, KeyHash> by_key;
  by_key.reserve(previous.size());
  for (const Contact& c : previous) by_key.emplace(c.key, &c);
  for (Contact& c : found) {
    const auto old = by_key.find(c.key);
    if (old != by_key.end()) {
      // The whole carried state; its predicted slip is the last step's slip, if sliding.
      c.state = old->second->state;
      ContactState& s = c.state;
      if (s.deferred) {
        // The change the last step left for this one (ContactState::deferred), made now.
        s.mode = s.deferred->mode;
        s.slide_sign = s.deferred->slide_sign;
        if (s.deferred->relock) s.t_lock = c.t;
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
