// One vertex-to-edge contact: its identity, its geometry at the start of the step, the
// state it carries across steps (open, sliding or locked; the shear spring's anchor; bond)
// and the results of the latest open-close iteration, kept apart (ContactState,
// ContactIterate).
#pragma once

#include <cstdint>
#include <optional>

#include "kinematics/types.hpp"

namespace dda {

enum class ContactMode : std::uint8_t { Open, Slide, Lock };

// Key of an unordered pair of blocks i and j (the joint a pair uses, World::pair_joint; the
// contacts a pair shares, carry_over).
inline std::uint64_t pair_key(int i, int j) {
  const auto lo = static_cast<std::uint64_t>(i < j ? i : j);
  const auto hi = static_cast<std::uint64_t>(i < j ? j : i);
  return (hi << 32) | lo;
}

// A contact's next mode: its slip direction if sliding, and whether a locked one takes a
// new shear anchor where the vertex is.
struct ModeChange {
  ContactMode mode = ContactMode::Open;
  int slide_sign = 0;
  bool relock = false;
  // A sliding contact that locks keeps the friction it carried: its new anchor lies this far
  // (m, along `tangent`, vertex minus anchor) behind the vertex, so that the shear spring
  // starts at that force (the elastic unloading of a return map starts on the limit). Zero
  // for a contact that closes.
  double lock_offset = 0.0;
};

struct ContactKey {
  int vertex_block = -1;
  int vertex = -1;
  int edge_block = -1;
  int edge = -1;
  friend bool operator==(const ContactKey&, const ContactKey&) = default;
};

// What a contact carries from one step to the next: carry_over copies it to the contact
// found again on the new configuration (and makes the deferred change); update_contact_modes
// changes it as the open-close loop settles (a bond breaks there); bond_closed_contacts
// (contact/bonding.hpp) bonds closed contacts, locking a sliding one.
struct ContactState {
  ContactMode mode = ContactMode::Open;
  int slide_sign = 0;     // +1 or -1: slip direction along `tangent` while sliding
  double t_lock = 0.0;    // edge parameter of the shear spring's anchor while locked
  bool bonded = false;    // cohesion and tensile strength act while bonded
  // The slip expected in this step (m, along `tangent`): the last step's. The normal gap and
  // the friction are measured at the edge point the vertex is expected to reach, not where
  // it started: a vertex sliding a distance s along an edge that turns by theta sees its gap
  // change by s theta more than the start point's motion says, and a corner sliding off a
  // tipping block started every step 24 um deeper than the step had predicted.
  double predicted_slip = 0.0;
  // Compression positive (N per metre). Written by each open-close iteration, and carried:
  // a sliding contact's friction in a step's first iteration uses the last step's.
  double normal_force = 0.0;
  // A change of mode the accepted solve asked for but did not wait for, because it was
  // within the contact resolution (contact/open_close_decision.hpp, kDeferShare): the contact
  // starts the next step in this mode (carry_over), anchored there if it locks.
  std::optional<ModeChange> deferred;
  // The augmented-Lagrangian multiplier of the normal spring, as a length (m; lambda / p):
  // the spring acts on gap - rest_shift, so it pushes with p rest_shift more than its
  // penetration says (Lin, Amadei et al. 1996). Grown by augment_multipliers
  // (solver/contact_assembly.cpp) when a settled solve leaves the contact deeper than its
  // target share of the allowance, kept while the contact stays closed (so a resting load
  // stays carried), set to zero where a solver opens the contact (Shi's loop in
  // solver/open_close_modes.cpp, the Newton solver in solver/contact_newton.cpp).
  double rest_shift = 0.0;
  // The energy of the shear spring at the end of the last accepted step (J per metre),
  // F^2 / 2 ks whether locked or sliding: the energy account treats a sliding contact as its
  // spring in series with the slider, so that the friction it carries when it relocks
  // (anchored S / ks behind the vertex) is energy it already held (solver/energy.cpp).
  double spring_energy = 0.0;
  // How far the contact has slid in accepted steps (m, summed whatever the direction): a
  // slip-weakening joint's strength follows it (law_at_slip, contact/joint_law.hpp).
  double slip_sum = 0.0;
};

// Results of the latest open-close iteration (mode_changes: counted over the loop), written
// by update_contact_modes; never carried (a contact found again starts the step at zero).
struct ContactIterate {
  double new_gap = 0.0;       // normal gap after the step's increments (m)
  double shear_force = 0.0;   // along `tangent`, on the vertex (N per metre)
  double slip = 0.0;          // the step's tangential displacement of the vertex against the edge (m)
  int mode_changes = 0;       // within this attempt's open-close loop
  // The mode and lock anchor the contact started the attempt with (recorded at its first
  // change; update_contact_modes): a lock made again within the loop starts from them.
  ContactMode start_mode = ContactMode::Open;
  double start_t_lock = 0.0;
};

struct Contact {
  ContactKey key;
  int joint = 0;  // index into the scene's joint materials
  // The rock bridge smeared over the contacted edge (BlockSpec::edge_bridges): its joint
  // material (-1: none) and the share of the edge it covers (contact_joint_law).
  int bridge_joint = -1;
  double bridge_share = 0.0;
  // The normal force it carried at the end of the last accepted step (N/m; 0 if new or
  // open then): the stress a Barton-Bandis joint's friction is taken at for the whole step
  // (law_at_stress), so that the step's friction does not move with its iterations.
  double start_normal_force = 0.0;

  // ---- geometry at the start of the step ----
  Vec2 vertex = Vec2::Zero();   // the entering vertex
  Vec2 edge_start = Vec2::Zero();
  Vec2 edge_end = Vec2::Zero();
  Vec2 tangent = Vec2::Zero();  // unit, along the edge
  Vec2 normal = Vec2::Zero();   // unit, out of the edge's block towards the vertex
  double gap = 0.0;             // signed normal distance, > 0 open, < 0 penetrating (m)
  double t = 0.0;               // projection of the vertex on the edge, 0..1 along it
  double length = 0.0;          // share of a face-to-face contact this vertex carries (m)
  // How deep it may penetrate after a step (m): the scene's allowed_penetration, or with the
  // converged contact solver and "auto", a share of the smaller free block's size
  // (contact_allowance, solver/world.hpp).
  double allowed_penetration = 0.0;

  ContactState state;
  ContactIterate iterate;

  Vec2 edge_point(double s) const { return edge_start + s * (edge_end - edge_start); }
  // A shear spring anchored at edge parameter `t_anchor`: its stretch at the step's start,
  // vertex minus anchor along `tangent` (m). And its inverse: the anchor's parameter for a
  // stretch `stretch` (ModeChange::lock_offset).
  double stretch_from(double t_anchor) const {
    return tangent.dot(vertex - edge_point(t_anchor));
  }
  double t_behind(double stretch) const { return t - stretch / (edge_end - edge_start).norm(); }
  // Where the normal gap and the friction are measured (see ContactState::predicted_slip;
  // only a contact that slid in the last step has one: every rule that ends a slide sets it
  // to zero, so the point stays put while a solver changes modes within a step).
  Vec2 measure_point() const {
    if (state.predicted_slip == 0.0) return edge_point(t);
    return edge_point(t + state.predicted_slip / (edge_end - edge_start).norm());
  }
};

}  // namespace dda
