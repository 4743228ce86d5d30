// Shi's open-close loop's rule for one contact, as a pure decision over plain data: given
// where the latest solve put the contact (its trial, measured by the solver), which mode it
// asks for, whether the loop lets it change now, and whether the change is within the
// contact resolution (so that, alone, it does not hold the loop up). The loop's policy, its
// shares of the allowed penetration and its chatter limit, lives here with it.
#pragma once

#include "contact/contact.hpp"
#include "contact/joint_law.hpp"

namespace dda {

// Slips below this share of the allowed penetration count as no slip (round-off), and a
// closed contact opens only beyond kOpenToleranceShare of it (see
// ContactTrial::open_tolerance). A coarser slip tolerance was tried and not kept
// (docs/contacts.md, "Rules tried and not kept").
constexpr double kSlipToleranceShare = 1e-6;
constexpr double kOpenToleranceShare = 1e-6;
// A contact that has changed mode this many times in one open-close loop may from then on
// only tighten (open -> sliding -> locked; a lock past its strength still slides;
// docs/contacts.md, "Chatter"): such a contact
// chatters between states that differ by nanometres (a brick's side against its
// neighbour), and the loop would otherwise be cut for nothing.
constexpr int kFreeModeChanges = 2;
// A contact held closed may end in tension by up to this share of the allowed penetration
// (0.64 um in a 1.6 m scene): the nanometre chatter of a brick's side stays inside it, while
// a spring that pulls a vertex back across a gap it started with (a box of tumbling blocks
// gained 1.5 % of its energy scale so) is beyond it and cuts the step.
constexpr double kHeldTensionShare = 1e-3;
// The contact resolution, as a share of the allowed penetration: a change of mode that the
// latest solve asks for by no more than this (a penetration, a gap, a spring's stretch past
// the friction limit or a reversed slip this small) does not, on its own, make the
// open-close loop go on. When every change a solve asks for is that small, the step is
// accepted and those contacts start the next step in their new mode (ContactState::deferred;
// Shi's code and ntdda go further and never iterate on a change of shear mode). Without it
// the side contacts of a settled wall, which carry almost nothing, flip between open,
// locked and sliding at nanometre scales every step. What the accepted step gets wrong is
// bounded by the resolution delta: a contact left open that penetrates delta brings
// p delta^2 / 2 into the next step, a sliding one that reverses by delta lets friction push
// forward over delta, and a lock held past the friction limit stores at most (ks delta)^2 /
// 2 ks more (conservatively); the energy account shows them.
constexpr double kDeferShare = 1e-5;

// The policy's numbers for a loop whose allowed penetration is `allowed` (m).
struct OpenClosePolicy {
  double slip_tolerance = 0.0;   // kSlipToleranceShare x allowed
  double open_tolerance = 0.0;   // kOpenToleranceShare x allowed
  double tension_band = 0.0;     // kHeldTensionShare x allowed
  double resolution = 0.0;       // kDeferShare x allowed
  int free_mode_changes = kFreeModeChanges;
};
OpenClosePolicy open_close_policy(double allowed);

// What one contact does after a solve.
struct OpenCloseDecision {
  ContactDecision next;
  bool changes = false;           // a change of mode the loop lets it make now
  bool deferrable = false;        // ... within the contact resolution
  double lock_offset = 0.0;       // ModeChange::lock_offset of a sliding contact that locks
  bool held_in_tension = false;   // held closed by the chatter rule beyond the tension band
};

// The decision for contact `c` (its state as the solve used it) at `trial`, under `law`
// with shear stiffness `ks`.
OpenCloseDecision decide_open_close(const Contact& c, const ContactTrial& trial,
                                    const JointLaw& law, double ks,
                                    const OpenClosePolicy& policy);

}  // namespace dda
