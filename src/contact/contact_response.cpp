#include "contact/contact_response.hpp"

#include <algorithm>
#include <cmath>

namespace dda {

ContactResponse contact_response(const JointLaw& law, const ContactSprings& springs, double gap,
                                 double stretch) {
  ContactResponse r;
  const bool coulomb_slip = springs.bonded && law.kind == JointLawKind::CoulombSlip;
  if (!springs.bonded && gap > 0.0) return r;  // open: no force of either kind
  r.normal_force = springs.normal_stiffness * (springs.rest_shift - gap);
  if (springs.bonded) {
    r.breaks = -r.normal_force > law.tensile_strength * springs.length;
  }
  r.strength = law.tan_phi * std::max(r.normal_force, 0.0);
  if (springs.bonded) r.strength += law.cohesion * springs.length;
  const double trial = -springs.shear_stiffness * stretch;
  if (springs.bonded && !coulomb_slip) {
    // Shi's brittle bond holds locked until it fails, in tension or in shear.
    r.mode = ContactMode::Lock;
    r.shear_force = trial;
    r.breaks = r.breaks || std::abs(trial) > r.strength;
    return r;
  }
  if (std::abs(trial) <= r.strength && r.strength > 0.0) {
    r.mode = ContactMode::Lock;
    r.shear_force = trial;
    return r;
  }
  r.mode = ContactMode::Slide;
  r.slide_sign = stretch >= 0.0 ? 1 : -1;
  r.shear_force = -r.slide_sign * r.strength;
  return r;
}

}  // namespace dda
