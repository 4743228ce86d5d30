// The contact room's joint law (src/contact/joint_law.hpp) on its own: the open, lock and
// slide transitions of an unbonded contact, which changes lie within the contact
// resolution, and a bonded contact that holds below its strength and breaks for good.
#include <catch2/catch.hpp>

#include "contact/joint_law.hpp"

using namespace dda;

// The decisions are discrete; the forces below are exact binary-friendly numbers chosen
// well away from the thresholds (except where the threshold itself is the point), so there
// is no tolerance.

namespace {

Contact contact_in(ContactMode mode, int slide_sign = 0, bool bonded = false,
                   double length = 0.0) {
  Contact c;
  c.state.mode = mode;
  c.state.slide_sign = slide_sign;
  c.state.bonded = bonded;
  c.length = length;
  return c;
}

ContactTrial closed(double normal_force, double shear_force, double slip = 0.0,
                    double slip_tolerance = 0.0) {
  ContactTrial t;
  t.new_gap = -1e-4;  // 0.1 mm penetration: closed
  t.normal_force = normal_force;
  t.shear_force = shear_force;
  t.slip = slip;
  t.slip_tolerance = slip_tolerance;
  return t;
}

ContactTrial separated(double tension = 0.0) {
  ContactTrial t;
  t.new_gap = 1e-4;  // 0.1 mm open
  t.tension = tension;
  return t;
}

}  // namespace

TEST_CASE("joint law: open, lock and slide transitions of an unbonded contact",
          "[joint-law]") {
  const JointLaw law{0.5, 0.0, 0.0};  // tan phi = 0.5, no cohesion, no tensile strength

  SECTION("open -> lock when it closes (and the anchor is set)") {
    const ContactDecision d = decide_contact_mode(contact_in(ContactMode::Open), closed(1000, 0),
                                                  law);
    CHECK(d.mode == ContactMode::Lock);
    CHECK(d.slide_sign == 0);
    CHECK_FALSE(d.bonded);
    CHECK(d.relock);
  }
  SECTION("open -> slide when a frictionless contact closes") {
    // No friction: no shear can be held, so it enters sliding along its slip (a lock spring
    // force -1e-3 on the vertex means it slipped towards +tangent). With friction it locks
    // (the section above), however large the shear.
    const JointLaw frictionless{0.0, 0.0, 0.0};
    ContactDecision d = decide_contact_mode(contact_in(ContactMode::Open), closed(1000, -1e-3),
                                            frictionless);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == 1);
    d = decide_contact_mode(contact_in(ContactMode::Open), closed(1000, 600), frictionless);
    CHECK(d.slide_sign == -1);
    d = decide_contact_mode(contact_in(ContactMode::Open), closed(1000, 1e6), law);
    CHECK(d.mode == ContactMode::Lock);
  }
  SECTION("open stays open while separated") {
    const ContactDecision d = decide_contact_mode(contact_in(ContactMode::Open), separated(), law);
    CHECK(d.mode == ContactMode::Open);
    CHECK_FALSE(d.relock);
  }
  SECTION("lock stays lock while |shear| <= tan phi N") {
    // N = 1000: friction limit 500. Shear 400 and exactly 500 (the rule is strict: >).
    for (double shear : {400.0, -400.0, 500.0}) {
      INFO("shear " << shear);
      const ContactDecision d =
          decide_contact_mode(contact_in(ContactMode::Lock), closed(1000, shear), law);
      CHECK(d.mode == ContactMode::Lock);
      CHECK(d.slide_sign == 0);
      CHECK_FALSE(d.relock);  // the anchor stays where it is
    }
  }
  SECTION("lock -> slide when |shear| > tan phi N, sliding against the shear force") {
    // N = 1000, limit 500. A spring force +600 along the tangent on the vertex means the
    // vertex has been displaced towards -tangent: it slips in -tangent, slide_sign -1.
    ContactDecision d = decide_contact_mode(contact_in(ContactMode::Lock), closed(1000, 600), law);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == -1);
    CHECK_FALSE(d.bonded);
    d = decide_contact_mode(contact_in(ContactMode::Lock), closed(1000, -600), law);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == 1);
  }
  SECTION("slide stays slide while it keeps slipping its way") {
    // Sliding +1, slip +1e-5 along the tangent (same way), tolerance 1e-9.
    ContactDecision d = decide_contact_mode(contact_in(ContactMode::Slide, 1),
                                            closed(1000, 0, 1e-5, 1e-9), law);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == 1);
    CHECK_FALSE(d.relock);
    d = decide_contact_mode(contact_in(ContactMode::Slide, -1), closed(1000, 0, -1e-5, 1e-9), law);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == -1);
  }
  SECTION("slide -> lock when the slip reverses by more than the tolerance") {
    // Sliding +1, slip -2e-9 against it, tolerance 1e-9: slip * sign = -2e-9 < -1e-9.
    ContactDecision d = decide_contact_mode(contact_in(ContactMode::Slide, 1),
                                            closed(1000, 0, -2e-9, 1e-9), law);
    CHECK(d.mode == ContactMode::Lock);
    CHECK(d.slide_sign == 0);
    CHECK(d.relock);  // a new anchor where the vertex is now
    // Sliding -1, slip +2e-9: reversed too.
    d = decide_contact_mode(contact_in(ContactMode::Slide, -1), closed(1000, 0, 2e-9, 1e-9), law);
    CHECK(d.mode == ContactMode::Lock);
    CHECK(d.relock);
  }
  SECTION("slide stays slide when the slip reverses by less than the tolerance") {
    // slip * sign = -0.5e-9 > -1e-9: round-off, not a reversal.
    ContactDecision d = decide_contact_mode(contact_in(ContactMode::Slide, 1),
                                            closed(1000, 0, -0.5e-9, 1e-9), law);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == 1);
    CHECK_FALSE(d.relock);
    d = decide_contact_mode(contact_in(ContactMode::Slide, -1), closed(1000, 0, 0.5e-9, 1e-9),
                            law);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == -1);
  }
  SECTION("closed -> open when the gap opens, from lock and from slide") {
    for (const Contact& c : {contact_in(ContactMode::Lock), contact_in(ContactMode::Slide, 1),
                             contact_in(ContactMode::Slide, -1)}) {
      const ContactDecision d = decide_contact_mode(c, separated(), law);
      CHECK(d.mode == ContactMode::Open);
      CHECK(d.slide_sign == 0);
      CHECK_FALSE(d.bonded);
      CHECK_FALSE(d.relock);
    }
  }
}

TEST_CASE("joint law: which changes lie within the contact resolution", "[joint-law]") {
  // tan phi 0.5, shear spring 1e10 N/m, resolution 1e-8 m: a closing contact may penetrate
  // 1e-8 m, an opening one open 1e-8 m, a lock's spring exceed friction by 1e10 x 1e-8 = 100 N,
  // a slide reverse by 1e-8 m. Values sit a factor 2 either side of each threshold.
  const JointLaw law{0.5, 0.0, 0.0};
  const double ks = 1e10, res = 1e-8;
  const auto within = [&](const Contact& c, const ContactTrial& t) {
    return change_within_resolution(c, decide_contact_mode(c, t, law), t, law, ks, res);
  };
  ContactTrial t;
  SECTION("closing: by the penetration") {
    t.new_gap = -0.5e-8;
    CHECK(within(contact_in(ContactMode::Open), t));
    t.new_gap = -2e-8;
    CHECK_FALSE(within(contact_in(ContactMode::Open), t));
  }
  SECTION("opening: by the gap") {
    t.new_gap = 0.5e-8;
    CHECK(within(contact_in(ContactMode::Lock), t));
    CHECK(within(contact_in(ContactMode::Slide, 1), t));
    t.new_gap = 2e-8;
    CHECK_FALSE(within(contact_in(ContactMode::Lock), t));
  }
  SECTION("lock -> slide: by the spring's force past friction over ks") {
    // N = 1000: friction 500; shear 550 exceeds it by 50 N (0.5e-8 m of stretch), 700 by 200 N.
    CHECK(within(contact_in(ContactMode::Lock), closed(1000, 550)));
    CHECK_FALSE(within(contact_in(ContactMode::Lock), closed(1000, -700)));
  }
  SECTION("slide -> lock: by the reversed slip") {
    CHECK(within(contact_in(ContactMode::Slide, 1), closed(1000, 0, -0.5e-8, 1e-10)));
    CHECK_FALSE(within(contact_in(ContactMode::Slide, 1), closed(1000, 0, -2e-8, 1e-10)));
  }
  SECTION("a bond that breaks is never within it") {
    const JointLaw bonding{0.5, 1e5, 2e5};
    const Contact c = contact_in(ContactMode::Lock, 0, true, 0.5);
    t.new_gap = 0.5e-8;
    t.tension = 2e5;  // beyond the capacity 1e5 N: breaks and opens, by a gap below res
    const ContactDecision d = decide_contact_mode(c, t, bonding);
    REQUIRE(d.mode == ContactMode::Open);
    CHECK_FALSE(change_within_resolution(c, d, t, bonding, ks, res));
  }
}

TEST_CASE("joint law: a bonded contact holds below its strength and breaks for good",
          "[joint-law]") {
  // tan phi 0.5, cohesion 1e5 Pa, tensile strength 2e5 Pa, contact length 0.5 m:
  // tension capacity 2e5 * 0.5 = 1e5 N; shear capacity 1e5 * 0.5 + 0.5 N = 5e4 + 0.5 N.
  const JointLaw law{0.5, 1e5, 2e5};
  const Contact bonded = contact_in(ContactMode::Lock, 0, true, 0.5);

  SECTION("holds in tension below (and at) the tensile strength") {
    for (double tension : {9e4, 1e5}) {
      INFO("tension " << tension);
      const ContactDecision d = decide_contact_mode(bonded, separated(tension), law);
      CHECK(d.mode == ContactMode::Lock);
      CHECK(d.bonded);
      CHECK_FALSE(d.relock);
    }
  }
  SECTION("holds in shear below cohesion plus friction") {
    // N = 2e4: capacity 5e4 + 1e4 = 6e4; shear 5.9e4 (well above friction alone, 1e4).
    for (double shear : {5.9e4, -5.9e4}) {
      INFO("shear " << shear);
      const ContactDecision d = decide_contact_mode(bonded, closed(2e4, shear), law);
      CHECK(d.mode == ContactMode::Lock);
      CHECK(d.bonded);
      CHECK_FALSE(d.relock);
    }
  }
  SECTION("breaks in tension: open, bond gone") {
    const ContactDecision d = decide_contact_mode(bonded, separated(1.1e5), law);
    CHECK(d.mode == ContactMode::Open);
    CHECK_FALSE(d.bonded);
    CHECK(d.slide_sign == 0);
  }
  SECTION("breaks in shear: slides (against the shear force), bond gone") {
    // N = 2e4, capacity 6e4, shear 6.1e4 > 6e4: broken; as an unbonded locked contact,
    // 6.1e4 > tan phi N = 1e4, so it slides; force +6.1e4 -> slip sign -1.
    ContactDecision d = decide_contact_mode(bonded, closed(2e4, 6.1e4), law);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == -1);
    CHECK_FALSE(d.bonded);
    d = decide_contact_mode(bonded, closed(2e4, -6.1e4), law);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == 1);
    CHECK_FALSE(d.bonded);
  }
  SECTION("broken stays broken: no strength and no cohesion any more") {
    // The same contact after its bond broke (bonded false), locked.
    const Contact broken = contact_in(ContactMode::Lock, 0, false, 0.5);
    // A small tension (a tenth of the former strength) now just opens it, and stays unbonded.
    ContactDecision d = decide_contact_mode(broken, separated(1e4), law);
    CHECK(d.mode == ContactMode::Open);
    CHECK_FALSE(d.bonded);
    // A shear of 3e4 with N = 2e4 (held while bonded: capacity 6e4) now exceeds friction
    // alone (1e4): it slides, still unbonded.
    d = decide_contact_mode(broken, closed(2e4, 3e4), law);
    CHECK(d.mode == ContactMode::Slide);
    CHECK(d.slide_sign == -1);
    CHECK_FALSE(d.bonded);
    // Re-closing an open broken contact locks it without bonding it again.
    d = decide_contact_mode(contact_in(ContactMode::Open, 0, false, 0.5), closed(2e4, 0), law);
    CHECK(d.mode == ContactMode::Lock);
    CHECK_FALSE(d.bonded);
  }
}

TEST_CASE("a joint with a rock bridge over part of it has the strengths in proportion to their "
          "lengths (Jennings)",
          "[contact][joints][bridges]") {
  JointLaw joint;
  joint.tan_phi = 0.5;
  joint.cohesion = 0.0;
  joint.tensile_strength = 0.0;
  joint.kind = JointLawKind::BrittleBond;
  JointLaw bridge;
  bridge.tan_phi = 1.0;
  bridge.cohesion = 1e6;
  bridge.tensile_strength = 4e5;
  bridge.kind = JointLawKind::CoulombSlip;
  // A quarter bridge: c = 0.75 x 0 + 0.25 x 1e6, and likewise; sums of two products, exact
  // in doubles for these binary fractions.
  const JointLaw mixed = bridged_law(joint, bridge, 0.25);
  CHECK(mixed.cohesion == 2.5e5);
  CHECK(mixed.tensile_strength == 1e5);
  CHECK(mixed.tan_phi == 0.625);
  CHECK(mixed.kind == JointLawKind::CoulombSlip);  // it breaks as the intact rock does
  // Neither weakens: the residual is the peak.
  CHECK(mixed.residual_slip == 0.0);
  // No bridge: the joint itself, law and all.
  const JointLaw none = bridged_law(joint, bridge, 0.0);
  CHECK(none.cohesion == 0.0);
  CHECK(none.kind == JointLawKind::BrittleBond);
  // A contact carries the bridge its face gets (Contact::bridge_joint, bridge_share).
  const std::vector<JointLaw> laws{joint, bridge};
  Contact c;
  c.joint = 0;
  CHECK(contact_joint_law(laws, c).cohesion == 0.0);
  c.bridge_joint = 1;
  c.bridge_share = 0.5;
  CHECK(contact_joint_law(laws, c).cohesion == 5e5);
  // A bridge that weakens: its residual cohesion mixed with the joint's (unweakened) one.
  bridge.residual_slip = 0.01;
  bridge.residual_cohesion = 2e5;
  bridge.residual_tan_phi = 0.5;
  const JointLaw weakening = bridged_law(joint, bridge, 0.5);
  CHECK(weakening.residual_slip == 0.01);
  CHECK(weakening.residual_cohesion == 1e5);
  CHECK(weakening.residual_tan_phi == 0.5);
}
