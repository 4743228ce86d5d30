// contact/carry_over: what a contact keeps from one step to the next (a pure function).
#include <algorithm>
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "contact/carry_over.hpp"

using namespace dda;

namespace {

Contact contact(int vertex, double gap, int joint = 0) {
  Contact c;
  c.key = {1, vertex, 0, 2};
  c.joint = joint;
  c.gap = gap;
  c.t = 0.25 * vertex;
  c.length = 0.5;  // a share of a face: a contact with strength to bond
  return c;
}

}  // namespace

TEST_CASE("carry_over: a known contact keeps its state, a new one starts by its gap",
          "[contact][carry]") {
  const std::vector<JointLaw> laws = {{0.5, 0.0, 0.0}, {0.5, 1e5, 0.0}};
  Contact old = contact(0, -1e-6);
  old.state.mode = ContactMode::Slide;
  old.state.slide_sign = -1;
  old.state.t_lock = 0.4;
  old.state.bonded = false;
  old.state.normal_force = 123.0;
  old.state.predicted_slip = 2e-4;
  old.iterate.new_gap = -3e-6;
  old.iterate.slip = 2e-4;
  old.iterate.mode_changes = 2;
  const std::vector<Contact> previous = {old};

  // Found again (fresh geometry, default state), plus a new closed and a new open one.
  std::vector<Contact> found = {contact(0, -2e-6), contact(1, 0.0, 1), contact(2, 1e-3, 1)};
  carry_over(previous, found, 1e-12, true, laws);
  CHECK(found[0].state.mode == ContactMode::Slide);
  CHECK(found[0].state.slide_sign == -1);
  CHECK(found[0].state.t_lock == 0.4);
  CHECK(found[0].state.normal_force == 123.0);
  CHECK(found[0].state.predicted_slip == 2e-4);
  CHECK(found[0].gap == -2e-6);  // the geometry is this step's
  // The last step's iteration results are not carried.
  CHECK(found[0].iterate.new_gap == 0.0);
  CHECK(found[0].iterate.slip == 0.0);
  CHECK(found[0].iterate.mode_changes == 0);
  // New and closed: locked where it is, bonded on the first step since its joint has cohesion.
  CHECK(found[1].state.mode == ContactMode::Lock);
  CHECK(found[1].state.t_lock == found[1].t);
  CHECK(found[1].state.bonded);
  // New and open: open, unbonded.
  CHECK(found[2].state.mode == ContactMode::Open);
  CHECK_FALSE(found[2].state.bonded);

  // After the first step, a new closed contact is not bonded (bonds form at the start or
  // when a stage asks, contact/bonding.hpp).
  std::vector<Contact> later = {contact(1, 0.0, 1)};
  carry_over({}, later, 1e-12, false, laws);
  CHECK(later[0].state.mode == ContactMode::Lock);
  CHECK_FALSE(later[0].state.bonded);
}

TEST_CASE("carry_over: a change the last step deferred is made as the contact is found again",
          "[contact][carry]") {
  const std::vector<JointLaw> laws = {{0.5, 0.0, 0.0}};
  // Locked with its anchor at 0.4, left to slide towards -tangent; open, left to lock;
  // sliding, left to open.
  Contact to_slide = contact(0, -1e-6);
  to_slide.state.mode = ContactMode::Lock;
  to_slide.state.t_lock = 0.4;
  to_slide.state.deferred = ModeChange{ContactMode::Slide, -1, false};
  Contact to_lock = contact(1, -1e-9);
  to_lock.state.deferred = ModeChange{ContactMode::Lock, 0, true};
  Contact to_open = contact(2, 1e-9);
  to_open.state.mode = ContactMode::Slide;
  to_open.state.slide_sign = 1;
  to_open.state.normal_force = 50.0;
  to_open.state.predicted_slip = 1e-5;
  to_open.state.deferred = ModeChange{ContactMode::Open, 0, false};
  std::vector<Contact> found = {contact(0, -1e-6), contact(1, -2e-9), contact(2, 2e-9)};
  found[1].t = 0.3;  // the vertex has moved along the edge since the last step
  carry_over({to_slide, to_lock, to_open}, found, 1e-12, false, laws);
  CHECK(found[0].state.mode == ContactMode::Slide);
  CHECK(found[0].state.slide_sign == -1);
  CHECK(found[1].state.mode == ContactMode::Lock);
  CHECK(found[1].state.t_lock == 0.3);  // anchored where the vertex is now
  CHECK(found[2].state.mode == ContactMode::Open);
  CHECK(found[2].state.normal_force == 0.0);
  CHECK(found[2].state.predicted_slip == 0.0);
  for (const Contact& c : found) CHECK_FALSE(c.state.deferred.has_value());
}

TEST_CASE("carry_over: a sliding contact deferred to lock keeps the friction it carried",
          "[contact][carry]") {
  // It slid (slide sign +1) against a friction of 600 N/m on the vertex (shear force -600
  // along the tangent); the loop left it to lock (ModeChange::lock_offset = -S / ks, the
  // stretch that carries S). Found again on a 2 m edge along x with the vertex at t = 0.5,
  // its anchor lies lock_offset behind the vertex, so the spring starts at -ks x stretch =
  // -600 N/m (docs/contacts.md, "Relocking"). The stretch (1.5e-7 m) is a difference of
  // coordinates of order 1, so its round-off is about 1e-16 / 1.5e-7 = 1e-9 of it: 1e-6.
  const std::vector<JointLaw> laws = {{0.5, 0.0, 0.0}};
  const double ks = 4e9, shear_force = -600.0;
  Contact slid = contact(0, -1e-6);
  slid.state.mode = ContactMode::Slide;
  slid.state.slide_sign = 1;
  slid.state.deferred = ModeChange{ContactMode::Lock, 0, true, -shear_force / ks};
  std::vector<Contact> found = {contact(0, -1e-6)};
  Contact& c = found[0];
  c.edge_start = Vec2(0.0, 0.0);
  c.edge_end = Vec2(2.0, 0.0);
  c.tangent = Vec2(1.0, 0.0);
  c.t = 0.5;
  c.vertex = Vec2(1.0, -1e-6);
  carry_over({slid}, found, 1e-12, false, laws);
  CHECK(c.state.mode == ContactMode::Lock);
  CHECK(c.state.t_lock == Approx(0.5 - 1.5e-7 / 2.0).epsilon(1e-12));
  CHECK(-ks * c.stretch_from(c.state.t_lock) == Approx(shear_force).epsilon(1e-6));
}

TEST_CASE("carry_over: each contact finds its own predecessor whatever the two lists' order",
          "[contact][carry]") {
  // carry_over looks for a predecessor first where the last one was found and then by key:
  // lists in the same order, one with contacts gone and new ones in between, one reversed
  // and one shuffled must all give every contact the state of the contact with its key.
  // Each previous contact carries its index as its normal force (N/m), so a wrong match
  // shows; the new contacts are open (gap 1 mm) and keep the default state.
  const std::vector<JointLaw> laws = {{0.5, 0.0, 0.0}};
  std::vector<Contact> previous;
  for (int k = 0; k < 40; ++k) {
    Contact c = contact(k % 4, 1e-3);
    c.key = {k / 4, k % 4, 40 + k / 4, (k * 7) % 4};
    c.state.mode = ContactMode::Lock;
    c.state.normal_force = k;
    previous.push_back(c);
  }
  const auto fresh = [](const Contact& c) {
    Contact f = contact(c.key.vertex, 1e-3);
    f.key = c.key;
    return f;
  };
  std::vector<std::vector<Contact>> orders(4);
  for (const Contact& c : previous) orders[0].push_back(fresh(c));  // the same order
  for (std::size_t k = 0; k < previous.size(); ++k) {  // every third gone, new ones between
    if (k % 3 == 1) continue;
    orders[1].push_back(fresh(previous[k]));
    if (k % 5 == 0) {
      Contact added = contact(0, 1e-3);
      added.key = {100 + static_cast<int>(k), 0, 200, 1};
      orders[1].push_back(added);
    }
  }
  orders[2] = std::vector<Contact>(orders[0].rbegin(), orders[0].rend());
  orders[3] = orders[1];
  std::shuffle(orders[3].begin(), orders[3].end(), std::mt19937(20261123u));
  for (std::size_t o = 0; o < orders.size(); ++o) {
    INFO("order " << o);
    std::vector<Contact> found = orders[o];
    carry_over(previous, found, 1e-12, false, laws);
    for (const Contact& c : found) {
      const auto old = std::find_if(previous.begin(), previous.end(),
                                    [&](const Contact& p) { return p.key == c.key; });
      if (old == previous.end()) {
        CHECK(c.state.mode == ContactMode::Open);
        CHECK(c.state.normal_force == 0.0);
      } else {
        CHECK(c.state.mode == ContactMode::Lock);
        CHECK(c.state.normal_force == old->state.normal_force);
      }
    }
  }
}

TEST_CASE("carry_over: a bond follows two coincident corners when their contact swaps roles",
          "[contact][carry]") {
  // Two unit squares side by side, block 1 on [0, 1] and block 2 on [1, 2], bonded along x = 1.
  // Their corners meet at (1, 1): last step the contact there was block 1's corner 2 on
  // block 2's left edge 3 (from (1, 1) to (1, 0)), locked at that edge's start; this step
  // round-off resolves the same pair of corners the other way round, block 2's corner 3 on
  // block 1's right edge 1 (from (1, 0) to (1, 1)), at its end.
  const std::vector<JointLaw> laws = {{0.0, 1e6, 1e6}};
  Contact old;
  old.key = {1, 2, 2, 3};
  old.vertex = Vec2(1.0, 1.0);
  old.edge_start = Vec2(1.0, 1.0);
  old.edge_end = Vec2(1.0, 0.0);
  old.t = 0.0;
  old.state.mode = ContactMode::Lock;
  old.state.t_lock = 0.0;
  old.state.bonded = true;
  old.state.normal_force = 50.0;
  Contact swapped;
  swapped.key = {2, 3, 1, 1};
  swapped.vertex = Vec2(1.0 + 1e-7, 1.0 - 2e-7);
  swapped.edge_start = Vec2(1.0, 0.0);
  swapped.edge_end = Vec2(1.0, 1.0);
  swapped.tangent = Vec2(0.0, 1.0);
  swapped.t = 1.0 - 2e-7;
  swapped.gap = 1e-7;  // open by a hair: a bonded contact in tension
  // And the bottom corners' contact, found again by its key: it keeps its own state.
  Contact bottom;
  bottom.key = {1, 1, 2, 3};
  bottom.vertex = Vec2(1.0, 0.0);
  bottom.edge_start = Vec2(1.0, 1.0);
  bottom.edge_end = Vec2(1.0, 0.0);
  bottom.t = 1.0;
  bottom.state.mode = ContactMode::Lock;
  bottom.state.t_lock = 1.0;
  bottom.state.bonded = true;
  Contact bottom_again = bottom;
  bottom_again.state = ContactState{};
  std::vector<Contact> found = {bottom_again, swapped};
  carry_over({old, bottom}, found, 1e-12, false, laws);
  CHECK(found[0].state.bonded);
  CHECK(found[0].state.t_lock == 1.0);
  // The corner's bond is handed over; the shear spring is anchored at block 1's corner,
  // the material point the old anchor was, so it keeps the slip between the two corners.
  CHECK(found[1].state.bonded);
  CHECK(found[1].state.mode == ContactMode::Lock);
  CHECK(found[1].state.t_lock == 1.0);
  CHECK(found[1].stretch_from(found[1].state.t_lock) == Approx(-2e-7).margin(1e-15));
  CHECK(found[1].state.normal_force == 50.0);

  // A bond is handed over once, and only by a contact that was lost: with the old contact
  // found again by its key, the swapped one is a new, unbonded contact.
  Contact old_again = old;
  old_again.state = ContactState{};
  std::vector<Contact> both = {old_again, swapped};
  carry_over({old, bottom}, both, 1e-12, false, laws);
  CHECK(both[0].state.bonded);
  CHECK_FALSE(both[1].state.bonded);
  CHECK(both[1].state.mode == ContactMode::Open);
  // Nor to a contact of the same pair at another corner.
  Contact elsewhere = swapped;
  elsewhere.vertex = Vec2(1.0, 0.0);
  elsewhere.t = 0.0;
  elsewhere.gap = 0.0;
  std::vector<Contact> far = {elsewhere};
  carry_over({old}, far, 1e-12, false, laws);
  CHECK_FALSE(far[0].state.bonded);
}
