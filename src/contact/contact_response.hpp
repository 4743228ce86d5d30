// A contact's response to a trial motion, as a pure function of where the motion puts it:
// the regularised Coulomb law behind the converged contact solver (solver/contact_newton.hpp,
// docs/contact-solver.md). Where Shi's open-close loop carries a mode from one iteration to
// the next and asks the joint law for the next one (contact/joint_law.hpp), here the mode is
// read off the trial itself: a normal penalty spring that only pushes (unless bonded), and a
// shear spring in series with a Coulomb slider, the elastic-plastic return of the shear
// stretch (Wriggers, Computational Contact Mechanics, 2006, ch. 5: penalty regularisation of
// Coulomb friction). The same answer at the same trial, whatever the iterate came from: a
// Newton iteration over it cannot cycle on its own history.
#pragma once

#include "contact/contact.hpp"
#include "contact/joint_law.hpp"

namespace dda {

// What the contact carries into the step's trials (fixed over the step).
struct ContactSprings {
  double normal_stiffness = 0.0;  // kn, the penalty (N/m)
  double shear_stiffness = 0.0;   // ks (N/m)
  double rest_shift = 0.0;        // the multiplier as a length (ContactState::rest_shift, m)
  bool bonded = false;            // cohesion and tensile strength act
  double length = 0.0;            // the face length the vertex carries (Contact::length, m)
};

struct ContactResponse {
  ContactMode mode = ContactMode::Open;
  int slide_sign = 0;         // sliding: the slip direction along the tangent (+1 or -1)
  // Compression positive (N per metre). Negative only on a bonded contact in tension.
  double normal_force = 0.0;
  // The shear force on the vertex along the tangent (N per metre): -ks s locked, the
  // strength against the slip when sliding, zero open.
  double shear_force = 0.0;
  // The shear strength the force was limited by (N per metre; 0 open).
  double strength = 0.0;
  // A bond that this trial breaks (tension beyond the tensile strength, or a brittle bond's
  // shear beyond its strength). The response above is still the bonded one: a bond breaks
  // only once the step has converged with it (ContactNewton), for good.
  bool breaks = false;
};

// The response at a trial whose geometric gap is `gap` (m, > 0 open) and whose shear spring
// is stretched by `stretch` (m, vertex minus anchor along the tangent):
//  - normal: unbonded, open when gap > 0, else pushing with kn (rest_shift - gap); bonded,
//    kn (rest_shift - gap) at either sign (a bond holds tension);
//  - shear, closed: the strength S = tan(phi) max(N, 0), plus cohesion x length while
//    bonded; locked (-ks stretch) while ks |stretch| <= S, else sliding towards the stretch
//    with -sign(stretch) S. A frictionless, unbonded contact always slides (S = 0: no
//    spring may hold it). A brittle bond never slides bonded: past S it breaks.
ContactResponse contact_response(const JointLaw& law, const ContactSprings& springs, double gap,
                                 double stretch);

}  // namespace dda
