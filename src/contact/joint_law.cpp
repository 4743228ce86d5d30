#include "contact/joint_law.hpp"

#include <algorithm>
#include <cmath>

namespace dda {
namespace {

// The shear spring force on the vertex opposes its slip: slip direction = -sign(force).
int slip_sign_of_force(double shear_force) { return shear_force > 0.0 ? -1 : 1; }

// A closed contact's shear decision: locked until the shear force passes `strength`, then
// sliding until its slip reverses. `bonded` is carried into the decision unchanged.
ContactDecision closed_shear(const Contact& c, const ContactTrial& trial, double strength,
                             bool bonded) {
  if (c.state.mode == ContactMode::Slide) {
    if (trial.slip * c.state.slide_sign < -trial.slip_tolerance) {
      return {ContactMode::Lock, 0, bonded, true};
    }
    return {ContactMode::Slide, c.state.slide_sign, bonded, false};
  }
  if (std::abs(trial.shear_force) > strength) {
    return {ContactMode::Slide, slip_sign_of_force(trial.shear_force), bonded, false};
  }
  return {ContactMode::Lock, 0, bonded, false};
}

ContactDecision unbonded(const Contact& c, const ContactTrial& trial, const JointLaw& law) {
  const double opens_above = c.state.mode == ContactMode::Open ? 0.0 : trial.open_tolerance;
  if (trial.new_gap > opens_above) return {ContactMode::Open, 0, false, false};
  switch (c.state.mode) {
    case ContactMode::Open:
      // Closing: Shi enters locked. A frictionless joint cannot hold any shear, so it enters
      // sliding in the direction of the trial's slip: entering locked, its shear spring
      // would stop the vertex on the edge and the loop would cycle open <-> lock. With
      // friction Shi's rule stays (docs/contacts.md, "Rules tried and not kept").
      if (law.tan_phi == 0.0 && trial.shear_force != 0.0) {
        return {ContactMode::Slide, slip_sign_of_force(trial.shear_force), false, false};
      }
      return {ContactMode::Lock, 0, false, true};
    case ContactMode::Lock:
    case ContactMode::Slide:
      return closed_shear(c, trial, law.tan_phi * trial.normal_force, false);
  }
  return {};
}

bool coulomb_slip_bond(const Contact& c, const JointLaw& law) {
  return c.state.bonded && law.kind == JointLawKind::CoulombSlip;
}

}  // namespace

JointLaw law_at_slip(const JointLaw& law, double slip_sum) {
  if (!(law.residual_slip > 0.0) || !(slip_sum > 0.0)) return law;
  const double share = std::min(1.0, slip_sum / law.residual_slip);
  JointLaw at = law;
  at.tan_phi = law.tan_phi + share * (law.residual_tan_phi - law.tan_phi);
  at.cohesion = law.cohesion + share * (law.residual_cohesion - law.cohesion);
  return at;
}

double barton_bandis_angle(double phi_r_deg, double jrc, double jcs, double sigma_n) {
  constexpr double kLargestAngle = 70.0;  // degrees
  if (!(sigma_n > 0.0)) return std::max(phi_r_deg, kLargestAngle);
  const double roughness = jrc * std::max(0.0, std::log10(jcs / sigma_n));
  return std::max(phi_r_deg, std::min(phi_r_deg + roughness, kLargestAngle));
}

JointLaw law_at_stress(const JointLaw& law, double normal_force, double length) {
  if (!(law.jcs > 0.0)) return law;
  const double sigma_n = length > 0.0 ? normal_force / length : law.jcs;
  const double phi_r = std::atan(law.tan_phi) * 180.0 / M_PI;
  JointLaw out = law;
  out.tan_phi = std::tan(barton_bandis_angle(phi_r, law.jrc, law.jcs, sigma_n) * M_PI / 180.0) /
                law.friction_divisor;
  out.jrc = 0.0;
  out.jcs = 0.0;
  out.friction_divisor = 1.0;
  return out;
}

JointLaw bridged_law(const JointLaw& joint, const JointLaw& bridge, double share) {
  if (!(share > 0.0)) return joint;
  const auto mix = [share](double j, double b) { return j + share * (b - j); };
  JointLaw out = joint;
  out.kind = bridge.kind;
  out.tan_phi = mix(joint.tan_phi, bridge.tan_phi);
  out.cohesion = mix(joint.cohesion, bridge.cohesion);
  out.tensile_strength = mix(joint.tensile_strength, bridge.tensile_strength);
  // Residuals: each law's own (its peak where it does not weaken), mixed, over the longer
  // of the two slip distances.
  const auto residual_tan = [](const JointLaw& l) { return l.residual_slip > 0.0 ? l.residual_tan_phi : l.tan_phi; };
  const auto residual_c = [](const JointLaw& l) { return l.residual_slip > 0.0 ? l.residual_cohesion : l.cohesion; };
  out.residual_slip = std::max(joint.residual_slip, bridge.residual_slip);
  out.residual_tan_phi = mix(residual_tan(joint), residual_tan(bridge));
  out.residual_cohesion = mix(residual_c(joint), residual_c(bridge));
  return out;
}

JointLaw contact_joint_law(const std::vector<JointLaw>& laws, const Contact& c) {
  const JointLaw& joint = laws[static_cast<std::size_t>(c.joint)];
  if (c.bridge_joint < 0) return joint;
  return bridged_law(joint, laws[static_cast<std::size_t>(c.bridge_joint)], c.bridge_share);
}

const char* joint_law_name(JointLawKind kind) {
  return kind == JointLawKind::CoulombSlip ? "coulomb_slip" : "brittle_bond";
}

std::optional<JointLawKind> joint_law_of_name(std::string_view name) {
  for (JointLawKind k : {JointLawKind::BrittleBond, JointLawKind::CoulombSlip}) {
    if (name == joint_law_name(k)) return k;
  }
  return std::nullopt;
}

double shear_strength(const Contact& c, const JointLaw& law, double normal_force) {
  const double friction = law.tan_phi * normal_force;
  return c.state.bonded ? friction + law.cohesion * c.length : friction;
}

double sliding_resistance(const Contact& c, const JointLaw& law, double normal_force) {
  const double friction = law.tan_phi * normal_force;
  return coulomb_slip_bond(c, law) ? friction + law.cohesion * c.length : friction;
}

ContactDecision decide_contact_mode(const Contact& c, const ContactTrial& trial,
                                    const JointLaw& law) {
  if (coulomb_slip_bond(c, law)) {
    if (trial.tension > law.tensile_strength * c.length) {
      Contact broken = c;  // pulled apart: the bond breaks for good, friction is left
      broken.state.bonded = false;
      broken.state.mode = ContactMode::Lock;
      return unbonded(broken, trial, {law.tan_phi, 0.0, 0.0, law.kind});
    }
    // A bonded contact carries tension, so it stays closed; in shear it slips and holds.
    return closed_shear(c, trial, shear_strength(c, law, trial.normal_force), true);
  }
  if (c.state.bonded) {
    const bool tension_fails = trial.tension > law.tensile_strength * c.length;
    const bool shear_fails = std::abs(trial.shear_force) >
                             law.cohesion * c.length + law.tan_phi * trial.normal_force;
    if (!tension_fails && !shear_fails) return {ContactMode::Lock, 0, true, false};
    // Broken for good: continue as an unbonded contact that was locked.
    Contact broken = c;
    broken.state.bonded = false;
    broken.state.mode = ContactMode::Lock;
    return unbonded(broken, trial, {law.tan_phi, 0.0, 0.0, law.kind});
  }
  return unbonded(c, trial, law);
}

bool change_allowed(const Contact& c, const ContactDecision& next, int free_changes) {
  if (c.iterate.mode_changes < free_changes) return true;
  if (next.bonded != c.state.bonded) return true;  // a bond breaks for good
  // A locked contact whose shear passes its strength always slides: held locked, nothing
  // would bound its shear (docs/contacts.md, "Chatter").
  if (c.state.mode == ContactMode::Lock && next.mode == ContactMode::Slide) return true;
  // ContactMode is ordered Open < Slide < Lock.
  return static_cast<int>(next.mode) > static_cast<int>(c.state.mode);
}

bool change_within_resolution(const Contact& c, const ContactDecision& next,
                              const ContactTrial& trial, const JointLaw& law, double ks,
                              double resolution) {
  // A bond that forms or breaks, or a brittle bond (which never changes mode bonded), is
  // never deferred; a Coulomb slip bond's lock <-> slide is a change like an unbonded one's.
  if (c.state.bonded != next.bonded) return false;
  if (c.state.bonded && law.kind != JointLawKind::CoulombSlip) return false;
  if (c.state.mode == ContactMode::Open) return -trial.new_gap <= resolution;  // closing
  // A locked contact left locked for the step keeps its shear spring: only if that spring
  // is within the resolution of its strength, whether it is to slide or to open (a heel
  // that lifts by nanometres must not keep a shear spring with no normal force).
  if (c.state.mode == ContactMode::Lock &&
      std::abs(trial.shear_force) - shear_strength(c, law, trial.normal_force) > ks * resolution) {
    return false;
  }
  if (next.mode == ContactMode::Open) return trial.new_gap <= resolution;  // opening
  if (c.state.mode == ContactMode::Lock) return true;                      // lock -> slide
  return std::abs(trial.slip) <= resolution;  // sliding: its slip reversed
}

}  // namespace dda
