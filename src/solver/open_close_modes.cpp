#include "solver/open_close_modes.hpp"

#include <algorithm>

#include "contact/joint_law.hpp"
#include "contact/open_close_decision.hpp"
#include "solver/contact_assembly.hpp"

namespace dda {
namespace {

Vec2 projection_point(const Contact& c) { return c.measure_point(); }

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
          shear_strength(c, contact_law(world, c), c.state.normal_force);
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
  const OpenClosePolicy policy = open_close_policy(world.allowed_penetration);
  // First every contact's decision on this solve (measured here, decided by the pure rule of
  // contact/open_close_decision.hpp), then (once it is known whether the loop goes on) the
  // changes.
  std::vector<OpenCloseDecision> pending(contacts.size());
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
    trial.slip_tolerance = policy.slip_tolerance;
    trial.open_tolerance = policy.open_tolerance;
    const JointLaw law = contact_law(world, c);
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
    const OpenCloseDecision decision = decide_open_close(c, trial, law, ks, policy);
    if (decision.held_in_tension) ++result.held_in_tension;
    pending[i] = decision;
    c.iterate.new_gap = trial.new_gap;
    c.iterate.slip = trial.slip;
    c.state.normal_force = trial.normal_force;
    c.iterate.shear_force = trial.shear_force;
  }
  // Changes within the resolution alone do not make the loop go on: if nothing else
  // changed, the step ends on this solve and those contacts start the next step in their
  // new mode; if the loop goes on anyway, they take it from the next iteration.
  int others = 0;
  for (const OpenCloseDecision& p : pending) others += p.changes && !p.deferrable ? 1 : 0;
  const bool defer = others == 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    Contact& c = contacts[i];
    const OpenCloseDecision& p = pending[i];
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
