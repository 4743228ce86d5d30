// contact/bonding: bond_closed_contacts, the rule that bonds the closed contacts of joints
// with strength at a stage's start (docs/scene-format.md, "stages"), on its own. (The
// stages that call it: tests/solver/test_stages.cpp.)
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "contact/bonding.hpp"

using namespace dda;
using Catch::Matchers::WithinAbs;

namespace {

Contact closed_contact(ContactMode mode, int joint) {
  Contact c;
  c.state.mode = mode;
  c.joint = joint;
  c.edge_start = Vec2(0.0, 0.0);
  c.edge_end = Vec2(4.0, 0.0);
  c.tangent = Vec2(1.0, 0.0);
  c.normal = Vec2(0.0, 1.0);
  c.t = 0.25;
  c.length = 2.0;  // half of a 4 m face: a contact with strength to bond
  c.state.t_lock = 0.2;
  c.iterate.slip = 0.1;
  c.state.slide_sign = mode == ContactMode::Slide ? 1 : 0;
  c.state.predicted_slip = mode == ContactMode::Slide ? 0.1 : 0.0;
  return c;
}

}  // namespace

TEST_CASE("bond_closed_contacts bonds closed contacts of joints with strength", "[stages][bonding]") {
  // Joint 0 has cohesion, joint 1 only a tensile strength, joint 2 friction only.
  const std::vector<JointLaw> laws = {{0.5, 1e4, 0.0}, {0.5, 0.0, 1e3}, {0.5, 0.0, 0.0}};
  std::vector<Contact> contacts = {
      closed_contact(ContactMode::Lock, 0),   // bonds, keeps its anchor
      closed_contact(ContactMode::Slide, 1),  // bonds, locked where its vertex now is
      closed_contact(ContactMode::Open, 0),   // open: not bonded
      closed_contact(ContactMode::Lock, 2),   // no strength: not bonded
      closed_contact(ContactMode::Lock, 0),   // already bonded: left alone, not counted
  };
  contacts[4].state.bonded = true;
  const std::vector<Contact> before = contacts;
  CHECK(bond_closed_contacts(contacts, laws) == 2);

  CHECK(contacts[0].state.bonded);
  CHECK(contacts[0].state.mode == ContactMode::Lock);
  // Its spring keeps the shear it carries.
  CHECK(contacts[0].state.t_lock == before[0].state.t_lock);

  CHECK(contacts[1].state.bonded);
  CHECK(contacts[1].state.mode == ContactMode::Lock);
  CHECK(contacts[1].state.slide_sign == 0);
  CHECK(contacts[1].state.predicted_slip == 0.0);
  // Anchored where the vertex ended its last step: t + slip / edge length = 0.25 + 0.1 / 4.
  CHECK_THAT(contacts[1].state.t_lock, WithinAbs(0.275, 1e-15));

  CHECK_FALSE(contacts[2].state.bonded);
  CHECK(contacts[2].state.mode == ContactMode::Open);
  CHECK_FALSE(contacts[3].state.bonded);
  CHECK(contacts[4].state.bonded);
  CHECK(contacts[4].state.t_lock == before[4].state.t_lock);

  // A bond broken earlier (closed, unbonded, on a joint with strength) forms again.
  std::vector<Contact> broken = {closed_contact(ContactMode::Lock, 0)};
  CHECK(bond_closed_contacts(broken, laws) == 1);
  CHECK(broken[0].state.bonded);
}

TEST_CASE("a contact of no length is not bonded", "[contact][bonding]") {
  // Two blocks meeting at a mesh node only carry a contact of no length (no face overlap):
  // its strength, c and T times its length, is nothing, so a bond would break at the first
  // load and be counted as broken (the crossed meshes of verification/vertical-cut "broke"
  // 213 such bonds in their consolidation).
  const std::vector<JointLaw> laws = {JointLaw{std::tan(0.5), 1e5, 1e5, JointLawKind::CoulombSlip}};
  std::vector<Contact> contacts = {closed_contact(ContactMode::Lock, 0)};
  contacts[0].length = 0.0;
  CHECK(bond_closed_contacts(contacts, laws) == 0);
  CHECK_FALSE(contacts[0].state.bonded);
}
