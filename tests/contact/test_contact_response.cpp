// The regularised Coulomb response of one contact (contact/contact_response.hpp), a pure
// function of the trial's gap and shear stretch, against the law written out by hand.
#include <catch2/catch.hpp>
#include <cmath>

#include "contact/contact_response.hpp"

using namespace dda;
using Catch::Matchers::WithinRel;

namespace {

constexpr double kKn = 5e10;         // the hard cases' penalty, 50 E at E = 1 GPa
constexpr double kKs = 0.4 * kKn;    // Shi's shear spring, kn / 2.5
const double kTanPhi = std::tan(30.0 * M_PI / 180.0);

ContactSprings springs(bool bonded = false, double rest_shift = 0.0) {
  return ContactSprings{kKn, kKs, rest_shift, bonded, 0.5};
}

JointLaw friction_only() { return JointLaw{kTanPhi, 0.0, 0.0, JointLawKind::BrittleBond}; }

}  // namespace

TEST_CASE("an unbonded contact that is open at the trial carries nothing", "[contact][newton]") {
  for (const double stretch : {-1e-3, 0.0, 1e-3}) {
    const ContactResponse r = contact_response(friction_only(), springs(), 1e-9, stretch);
    CHECK(r.mode == ContactMode::Open);
    CHECK(r.normal_force == 0.0);
    CHECK(r.shear_force == 0.0);
    CHECK_FALSE(r.breaks);
  }
  // A multiplier pushes while the contact is closed, never across an open gap: the contact
  // opens by its geometric gap (solver/step.cpp's augmentation).
  CHECK(contact_response(friction_only(), springs(false, 1e-6), 1e-9, 0.0).normal_force == 0.0);
}

TEST_CASE("a closed contact locks within its friction strength and slides beyond it",
          "[contact][newton]") {
  const double gap = -2e-6;                  // 2 um penetration
  const double normal = kKn * 2e-6;          // 1e5 N/m
  const double strength = kTanPhi * normal;  // 57.7 kN/m
  const double elastic = strength / kKs;     // the stretch at which it starts to slide
  SECTION("within the strength: the shear spring") {
    const ContactResponse r = contact_response(friction_only(), springs(), gap, 0.5 * elastic);
    CHECK(r.mode == ContactMode::Lock);
    CHECK_THAT(r.normal_force, WithinRel(normal, 1e-15));
    CHECK_THAT(r.shear_force, WithinRel(-0.5 * strength, 1e-15));
  }
  SECTION("beyond it, either way: the strength against the stretch") {
    for (const int sign : {1, -1}) {
      const ContactResponse r = contact_response(friction_only(), springs(), gap, sign * 3.0 * elastic);
      CHECK(r.mode == ContactMode::Slide);
      CHECK(r.slide_sign == sign);
      CHECK_THAT(r.shear_force, WithinRel(-sign * strength, 1e-15));
      CHECK_THAT(r.strength, WithinRel(strength, 1e-15));
    }
  }
  SECTION("a multiplier adds kn rest_shift to the normal force and so to the strength") {
    const ContactResponse r = contact_response(friction_only(), springs(false, 1e-6), gap, 0.0);
    CHECK_THAT(r.normal_force, WithinRel(kKn * 3e-6, 1e-15));
  }
}

TEST_CASE("a frictionless contact always slides and never holds shear", "[contact][newton]") {
  const JointLaw smooth{0.0, 0.0, 0.0, JointLawKind::BrittleBond};
  for (const double stretch : {-1e-9, 0.0, 1e-9}) {
    const ContactResponse r = contact_response(smooth, springs(), -1e-6, stretch);
    CHECK(r.mode == ContactMode::Slide);
    CHECK(r.shear_force == 0.0);
  }
}

TEST_CASE("an unbonded contact never pulls", "[contact][newton]") {
  // At any gap and stretch the normal force is compression or nothing.
  for (const double gap : {-1e-3, -1e-12, 0.0, 1e-12, 1e-3}) {
    for (const double stretch : {-1e-3, 0.0, 1e-3}) {
      CHECK(contact_response(friction_only(), springs(), gap, stretch).normal_force >= 0.0);
    }
  }
}

TEST_CASE("a brittle bond holds tension and shear up to its strengths, then breaks",
          "[contact][newton]") {
  const JointLaw bond{kTanPhi, 1e5, 2e4, JointLawKind::BrittleBond};  // c, T in Pa; length 0.5 m
  SECTION("in tension below T x length it holds, locked") {
    const double gap = 0.9 * 2e4 * 0.5 / kKn;
    const ContactResponse r = contact_response(bond, springs(true), gap, 0.0);
    CHECK(r.mode == ContactMode::Lock);
    CHECK_THAT(r.normal_force, WithinRel(-0.9 * 1e4, 1e-12));
    CHECK_FALSE(r.breaks);
    CHECK(contact_response(bond, springs(true), 1.1 * 2e4 * 0.5 / kKn, 0.0).breaks);
  }
  SECTION("in shear it stays locked beyond c x length + tan(phi) N, and breaks") {
    const double strength = 1e5 * 0.5 + kTanPhi * kKn * 1e-6;
    const ContactResponse held = contact_response(bond, springs(true), -1e-6, -0.99 * strength / kKs);
    CHECK(held.mode == ContactMode::Lock);
    CHECK_FALSE(held.breaks);
    const ContactResponse broken = contact_response(bond, springs(true), -1e-6, -1.01 * strength / kKs);
    CHECK(broken.mode == ContactMode::Lock);  // bonded until the step has converged with it
    CHECK(broken.breaks);
  }
}

TEST_CASE("the response of a Coulomb slip bond: it slides with its cohesion, breaks only in tension",
          "[contact][newton]") {
  const JointLaw slip{kTanPhi, 1e5, 2e4, JointLawKind::CoulombSlip};
  const double strength = 1e5 * 0.5 + kTanPhi * kKn * 1e-6;
  const ContactResponse r = contact_response(slip, springs(true), -1e-6, 2.0 * strength / kKs);
  CHECK(r.mode == ContactMode::Slide);
  CHECK(r.slide_sign == 1);
  CHECK_THAT(r.shear_force, WithinRel(-strength, 1e-15));
  CHECK_FALSE(r.breaks);
  // In tension (below T x length) the strength is the cohesion alone: no friction from a
  // negative normal force.
  const ContactResponse pulled = contact_response(slip, springs(true), 1e-7, 1.0);
  CHECK_THAT(pulled.strength, WithinRel(1e5 * 0.5, 1e-15));
  CHECK_FALSE(pulled.breaks);
}
