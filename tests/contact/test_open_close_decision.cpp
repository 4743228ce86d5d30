// Shi's open-close rule for one contact (src/contact/open_close_decision.hpp) on its own:
// the policy's numbers, a free change, the chatter rule holding a contact closed (and
// whether it is then in tension beyond the band), a change within the contact resolution,
// and a sliding contact that locks at the friction it carried.
#include <catch2/catch.hpp>

#include "contact/open_close_decision.hpp"

using namespace dda;

// The decisions are discrete and the numbers below are binary-friendly and far from the
// thresholds (except where a threshold is the point), so there is no tolerance but for the
// policy's products, which are one rounding each.

namespace {

Contact contact_in(ContactMode mode, int changes = 0, int slide_sign = 0) {
  Contact c;
  c.state.mode = mode;
  c.state.slide_sign = slide_sign;
  c.iterate.mode_changes = changes;
  return c;
}

ContactTrial separated(double gap) {
  ContactTrial t;
  t.new_gap = gap;
  return t;
}

}  // namespace

TEST_CASE("open-close decision: the policy scales with the allowed penetration",
          "[joint-law]") {
  const OpenClosePolicy p = open_close_policy(0.01);
  CHECK(p.slip_tolerance == Approx(1e-8).epsilon(1e-15));
  CHECK(p.open_tolerance == Approx(1e-8).epsilon(1e-15));
  CHECK(p.tension_band == Approx(1e-5).epsilon(1e-15));
  CHECK(p.resolution == Approx(1e-7).epsilon(1e-15));
  CHECK(p.free_mode_changes == 2);
}

TEST_CASE("open-close decision: free changes, the chatter rule and held tension",
          "[joint-law]") {
  const JointLaw law{0.5, 0.0, 0.0};  // tan phi = 0.5, no bond
  const double ks = 1e9;
  const OpenClosePolicy policy = open_close_policy(1e-3);  // band 1e-6 m, resolution 1e-8 m

  SECTION("a locked contact that opens by 1 mm opens while it has changes left") {
    const OpenCloseDecision d =
        decide_open_close(contact_in(ContactMode::Lock, 1), separated(1e-3), law, ks, policy);
    CHECK(d.next.mode == ContactMode::Open);
    CHECK(d.changes);
    CHECK_FALSE(d.deferrable);  // 1 mm is far beyond the resolution
    CHECK_FALSE(d.held_in_tension);
  }
  SECTION("after two changes it is held closed, and 1 mm of opening is tension beyond the band") {
    const OpenCloseDecision d =
        decide_open_close(contact_in(ContactMode::Lock, 2), separated(1e-3), law, ks, policy);
    CHECK_FALSE(d.changes);
    CHECK(d.held_in_tension);
  }
  SECTION("held closed at an opening inside the band is no tension to cut for") {
    const OpenCloseDecision d = decide_open_close(contact_in(ContactMode::Lock, 2),
                                                  separated(5e-7), law, ks, policy);
    CHECK_FALSE(d.changes);
    CHECK_FALSE(d.held_in_tension);
  }
  SECTION("an opening within the resolution is a change that does not hold the loop up") {
    const OpenCloseDecision d = decide_open_close(contact_in(ContactMode::Lock, 0),
                                                  separated(5e-9), law, ks, policy);
    CHECK(d.next.mode == ContactMode::Open);
    CHECK(d.changes);
    CHECK(d.deferrable);
  }
}

TEST_CASE("open-close decision: a sliding contact whose slip reverses locks at its friction",
          "[joint-law]") {
  const JointLaw law{0.5, 0.0, 0.0};
  const double ks = 1e9;
  const OpenClosePolicy policy = open_close_policy(1e-3);
  // Sliding towards +tangent against a friction force of -500 N (tan phi x 1000 N); the
  // solve reverses the slip by 1 mm, far beyond the slip tolerance.
  ContactTrial t;
  t.new_gap = -1e-4;
  t.normal_force = 1000.0;
  t.shear_force = -500.0;
  t.slip = -1e-3;
  t.slip_tolerance = policy.slip_tolerance;
  const OpenCloseDecision d =
      decide_open_close(contact_in(ContactMode::Slide, 0, +1), t, law, ks, policy);
  CHECK(d.next.mode == ContactMode::Lock);
  CHECK(d.changes);
  // Its spring starts at the friction it carried: an offset of 500 N / ks = 5e-7 m.
  CHECK(d.lock_offset == Approx(5e-7).epsilon(1e-15));
}
