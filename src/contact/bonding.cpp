#include "contact/bonding.hpp"

#include <cassert>

namespace dda {

int bond_closed_contacts(std::vector<Contact>& contacts, const std::vector<JointLaw>& laws) {
  int formed = 0;
  for (Contact& c : contacts) {
    if (c.mode == ContactMode::Open || c.bonded) continue;
    assert(c.joint >= 0 && static_cast<std::size_t>(c.joint) < laws.size());
    const JointLaw& law = laws[static_cast<std::size_t>(c.joint)];
    if (law.cohesion <= 0.0 && law.tensile_strength <= 0.0) continue;
    if (c.mode == ContactMode::Slide) {
      const double edge_length = (c.edge_end - c.edge_start).norm();
      c.t_lock = c.t + c.slip / edge_length;
      c.mode = ContactMode::Lock;
      c.slide_sign = 0;
      c.predicted_slip = 0.0;  // only a sliding contact measures ahead (contact.hpp)
    }
    c.bonded = true;
    ++formed;
  }
  return formed;
}

}  // namespace dda
