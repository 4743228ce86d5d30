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
      const Contact& o = *old->second;
      c.mode = o.mode;
      c.slide_sign = o.slide_sign;
      c.t_lock = o.t_lock;
      c.bonded = o.bonded;
      c.normal_force = o.normal_force;
      c.predicted_slip = o.predicted_slip;  // the last step's slip, if sliding
      if (o.deferred) {
        // The change the last step left for this one (Contact::deferred).
        c.mode = o.deferred->mode;
        c.slide_sign = o.deferred->slide_sign;
        if (o.deferred->relock) c.t_lock = c.t;
        if (c.mode != ContactMode::Slide) c.predicted_slip = 0.0;
        if (c.mode == ContactMode::Open) c.normal_force = 0.0;
      }
    } else if (c.gap <= touching) {
      c.mode = ContactMode::Lock;
      c.t_lock = c.t;
      const JointLaw& law = laws[static_cast<std::size_t>(c.joint)];
      c.bonded = bond_new_closed && (law.cohesion > 0.0 || law.tensile_strength > 0.0);
    }
  }
}

}  // namespace dda
