#include "contact/open_close_decision.hpp"

#include <algorithm>

namespace dda {

OpenClosePolicy open_close_policy(double allowed) {
  OpenClosePolicy p;
  p.slip_tolerance = kSlipToleranceShare * allowed;
  p.open_tolerance = kOpenToleranceShare * allowed;
  p.tension_band = kHeldTensionShare * allowed;
  p.resolution = kDeferShare * allowed;
  return p;
}

OpenCloseDecision decide_open_close(const Contact& c, const ContactTrial& trial,
                                    const JointLaw& law, double ks,
                                    const OpenClosePolicy& policy) {
  const auto differs = [&c](const ContactDecision& next) {
    return next.mode != c.state.mode || next.slide_sign != c.state.slide_sign ||
           next.bonded != c.state.bonded;
  };
  ContactDecision next = decide_contact_mode(c, trial, law);
  bool changes = differs(next);
  const bool wants_to_open = changes && next.mode == ContactMode::Open;
  if (changes && !change_allowed(c, next, policy.free_mode_changes) && wants_to_open) {
    // Held closed although it would open: it must still obey the closed contact's rules
    // (a sliding one whose slip reverses locks), else its friction pushes forward.
    ContactTrial closed = trial;
    closed.new_gap = std::min(trial.new_gap, 0.0);
    next = decide_contact_mode(c, closed, law);
    changes = differs(next);
  }
  OpenCloseDecision decision;
  decision.next = next;
  decision.changes = changes && change_allowed(c, next, policy.free_mode_changes);
  decision.held_in_tension = !decision.changes && wants_to_open && trial.new_gap > policy.tension_band;
  decision.deferrable = decision.changes && change_within_resolution(c, next, trial, law, ks, policy.resolution);
  // A sliding contact that locks starts its shear spring at the friction it carried in
  // this solve (trial.shear_force), not at zero: locked afresh, it would have to slip
  // S / ks again before carrying it, a slip per relock (docs/contacts.md, "Relocking").
  if (next.relock && c.state.mode == ContactMode::Slide) decision.lock_offset = -trial.shear_force / ks;
  return decision;
}

}  // namespace dda
