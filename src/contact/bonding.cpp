#include "contact/bonding.hpp"

#include <cassert>

namespace dda {

int bond_closed_contacts(std::vector<Contact>& contacts, const std::vector<JointLaw>& laws) {
  int formed = 0;
  for (Contact& c : contacts) {
    if (c.state.mode == ContactMode::Open || c.state.bonded) continue;
    assert(c.joint >= 0 && static_cast<std::size_t>(c.joint) < laws.size());
    const JointLaw law = contact_joint_law(laws, c);
    if (law.cohesion <= 0.0 && law.tensile_strength <= 0.0) continue;
    // A contact of no length (two blocks meeting at a node only) has no strength to bond.
    if (c.length <= 0.0) continue;
    if (c.state.mode == ContactMode::Slide) {
      const double edge_length = (c.edge_end - c.edge_start).norm();
      c.state.t_lock = c.t + c.iterate.slip / edge_length;
      c.state.mode = ContactMode::Lock;
      c.state.slide_sign = 0;
      c.state.predicted_slip = 0.0;  // only a sliding contact measures ahead (contact.hpp)
    }
    c.state.bonded = true;
    ++formed;
  }
  return formed;
}

}  // namespace dda
