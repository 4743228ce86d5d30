#include "solver/open_close_modes.hpp"

#include <algorithm>

#include "contact/joint_law.hpp"
#include "solver/contact_assembly.hpp"

namespace dda {
namespace {

Vec2 projection_point(const Contact& c) { return c.measure_point(); }

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

// Where a contact that locks again within the open-close loop anchors its shear spring
// (docs/contacts.md, "Relocking"). What the accepted step will say is decided by the whole
// loop, so it starts from what the contact carried at the step's start: a contact that
// started locked keeps its anchor, its shear capped at its present strength (the return map
// of a spring the loop found past it); one that started sliding starts at the friction it
// carries (`slide_offset`, vertex minus anchor along the tangent); one that started open, at
// zero (Shi's lock on closing).
double relock_anchor(const World& world, const Contact& c, double slide_offset, double ks) {
  switch (c.iterate.start_mode) {
    case ContactMode::Open:
      return c.t;
    case ContactMode::Slide:
      return c.t_behind(slide_offset);
    case ContactMode::Lock: {
      const double stretch = c.stretch_from(c.iterate.start_t_lock);
      const double strength =
          shear_strength(c, world.joint_laws[c.joint], c.state.normal_force);
      return c.t_behind(std::clamp(ks * stretch, -strength, strength) / ks);
    }
  }
  return c.t;
}

}  // namespace

ContactUpdate update_contact_modes(const World& world, std::vector<Contact>& contacts,
                                   const Eigen::VectorXd& d, const StepContext& ctx) {
  const double kn = ctx.penalty;
  const double ks = shear_stiffness(ctx.penalty);
  ContactUpdate result;
  const double tension_band = kHeldTensionShare * world.allowed_penetration;
  const double resolution = kDeferShare * world.allowed_penetration;
  // First every contact's decision on this solve, then (once it is known whether the loop
  // goes on) the changes.
  struct Pending {
    ContactDecision next;
    bool changes = false;
    bool deferrable = false;
    double lock_offset = 0.0;  // ModeChange::lock_offset
  };
  std::vector<Pending> pending(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    const Vec2 p0 = projection_point(c);
    ContactTrial trial;
    trial.new_gap = c.gap + evaluate(world, c, relative_along(world, ctx, c, p0, c.normal), d);
    // The spring acts on the gap less the multiplier's shift (zero unless augmented); the
    // contact opens and closes by the geometric gap, so a shift never holds a gap open.
    const double spring_gap = trial.new_gap - c.state.rest_shift;
    trial.normal_force = kn * std::max(0.0, -spring_gap);
    trial.tension = kn * std::max(0.0, spring_gap);
    trial.slip = evaluate(world, c, relative_along(world, ctx, c, p0, c.tangent), d);
    trial.slip_tolerance = kSlipToleranceShare * world.allowed_penetration;
    trial.open_tolerance = kOpenToleranceShare * world.allowed_penetration;
    const JointLaw& law = world.joint_laws[c.joint];
    if (c.state.mode == ContactMode::Lock) {
      const Vec2 anchor = c.edge_point(c.state.t_lock);
      const double shear = c.tangent.dot(c.vertex - anchor) +
                           evaluate(world, c, relative_along(world, ctx, c, anchor, c.tangent), d);
      trial.shear_force = -ks * shear;
    } else if (c.state.mode == ContactMode::Open) {
      trial.shear_force = -ks * trial.slip;
    } else if (c.state.mode == ContactMode::Slide) {
      trial.shear_force = -c.state.slide_sign * sliding_resistance(c, law, c.state.normal_force);
    }
    const auto differs = [&c](const ContactDecision& next) {
      return next.mode != c.state.mode || next.slide_sign != c.state.slide_sign ||
             next.bonded != c.state.bonded;
    };
    ContactDecision next = decide_contact_mode(c, trial, law);
    bool changes = differs(next);
    const bool wants_to_open = changes && next.mode == ContactMode::Open;
    if (changes && !change_allowed(c, next, kFreeModeChanges) && wants_to_open) {
      // Held closed although it would open: it must still obey the closed contact's rules
      // (a sliding one whose slip reverses locks), else its friction pushes forward.
      ContactTrial closed = trial;
      closed.new_gap = std::min(trial.new_gap, 0.0);
      next = decide_contact_mode(c, closed, law);
      changes = differs(next);
    }
    Pending& p = pending[i];
    p.next = next;
    p.changes = changes && change_allowed(c, next, kFreeModeChanges);
    if (!p.changes && wants_to_open && trial.new_gap > tension_band) ++result.held_in_tension;
    p.deferrable = p.changes && change_within_resolution(c, next, trial, law, ks, resolution);
    // A sliding contact that locks starts its shear spring at the friction it carried in
    // this solve (trial.shear_force), not at zero: locked afresh, it would have to slip
    // S / ks again before carrying it, a slip per relock (docs/contacts.md, "Relocking").
    if (next.relock && c.state.mode == ContactMode::Slide) p.lock_offset = -trial.shear_force / ks;
    c.iterate.new_gap = trial.new_gap;
    c.iterate.slip = trial.slip;
    c.state.normal_force = trial.normal_force;
    c.iterate.shear_force = trial.shear_force;
  }
  // Changes within the resolution alone do not make the loop go on: if nothing else
  // changed, the step ends on this solve and those contacts start the next step in their
  // new mode; if the loop goes on anyway, they take it from the next iteration.
  int others = 0;
  for (const Pending& p : pending) others += p.changes && !p.deferrable ? 1 : 0;
  const bool defer = others == 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    const Pending& p = pending[i];
    c.state.deferred.reset();
    if (p.changes && p.deferrable && defer) {
      c.state.deferred = ModeChange{p.next.mode, p.next.slide_sign, p.next.relock, p.lock_offset};
    } else if (p.changes) {
      if (!p.deferrable) ++result.changed;
      if (c.iterate.mode_changes == 0) {
        c.iterate.start_mode = c.state.mode;
        c.iterate.start_t_lock = c.state.t_lock;
      }
      ++c.iterate.mode_changes;
      c.state.mode = p.next.mode;
      c.state.slide_sign = p.next.slide_sign;
      c.state.bonded = p.next.bonded;
      if (p.next.relock) c.state.t_lock = relock_anchor(world, c, p.lock_offset, ks);
    }
    // A sliding contact's normal spring moves to where the vertex now slides to (see
    // ContactState::predicted_slip); the next iteration measures there.
    c.state.predicted_slip = predicted_slip(world, c);
    // (A held contact keeps its mode, but its forces follow the latest solve.)
    if (c.state.mode == ContactMode::Open) {
      c.state.rest_shift = 0.0;
      c.state.normal_force = 0.0;
      c.iterate.shear_force = 0.0;
    }
  }
  return result;
}

double predicted_slip(const World& world, const Contact& c) {
  if (c.state.mode != ContactMode::Slide) return 0.0;
  // Bounded by what the two blocks may move this step: an iteration far from the solution
  // must not carry the measure point off the edge; a larger slip is cut by the displacement
  // check.
  const double reach = world.blocks[static_cast<std::size_t>(c.key.vertex_block)].reach +
                       world.blocks[static_cast<std::size_t>(c.key.edge_block)].reach;
  return std::clamp(c.iterate.slip, -reach, reach);
}

}  // namespace dda
