// Contacts inside the open-close loop: their springs and friction forces in the global
// system (Shi 1988, ch. 4), and after each solve, what each contact does next.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact/contact.hpp"
#include "solver/sparse_cholesky.hpp"
#include "solver/block_system.hpp"
#include "solver/energy_terms.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// How a contact sees the unknowns: a scalar measure g = g0 + a.d_v + b.d_e, with d_v the
// vertex block's increments and d_e the edge block's.
struct Measure {
  Vec6 on_vertex_block = Vec6::Zero();
  Vec6 on_edge_block = Vec6::Zero();
};

// Relative displacement of the vertex against a material point `x` of the edge block,
// projected on `dir`, as a measure of the step's increments (T of this iteration).
Measure relative_along(const World& world, const StepContext& ctx, const Contact& c,
                       const Vec2& x, const Vec2& dir);

// The measure's value a.d_v + b.d_e at increments d (fixed blocks carry none).
double evaluate(const World& world, const Contact& c, const Measure& m, const Eigen::VectorXd& d);

// Normal spring (stiffness p) on closed contacts, shear spring (p / 2.5, Shi's usual ratio)
// on locked ones, Coulomb friction tan(phi) N against the slip on sliding ones.
void add_contact_terms(const World& world, std::vector<Contact>& contacts,
                       const StepContext& ctx, BlockSystem& system);

// The stiffness a contact adds to K in its present mode, as rank-one terms c c^T with
// c = sqrt(k) m (normal spring when closed, shear spring when locked); appended to `out`.
void contact_spring_terms(const World& world, const Contact& c, const StepContext& ctx,
                          std::vector<RankOneTerm>& out);

// One augmented-Lagrangian update (Lin, Amadei et al. 1996): every closed contact that
// penetrates deeper than `target_share` of its allowed penetration adds the excess to its multiplier
// (ContactState::rest_shift; lambda += p (|g| - target), as a length), so the next solve,
// with the same matrix, pushes it back to about `target`. Returns how many grew.
// In a dynamic step (dynamic_coefficient > 0) only where the step is long against the
// contact's own period: penalty x dt^2 at least twice the mass of the lighter free block it
// touches, so that the spring outweighs that block's inertia term 2m/dt^2. In a shorter step
// a penetration beyond the allowance is an impact (step.cpp, kDeepeningShare) the spring
// resolves over several steps, and a multiplier, a force no spring stored, would push the
// rebounding block out with work nothing put in: a rigid square falling at 5 m/s onto a
// floor at steps of 1e-6 s left at 10.8 m/s. (A static step starts from rest: no impact.)
int augment_multipliers(const World& world, std::vector<Contact>& contacts, double target_share,
                        const StepContext& ctx);

// The contacts' share of an accepted step's energy account (before the configuration
// update, with the modes and forces the contact solver left): their normal springs' and
// shear springs' backward-Euler losses, the multipliers' work, friction's dissipation (and
// any push forward, which the guard then names), each contact noted with what it brought in.
void book_contact_step(const std::vector<Contact>& contacts, const StepContext& ctx,
                       StepEnergy& step);

// Adds the energy the contacts' springs hold now to `energy` (closed contacts' normal
// springs at either sign of the gap, penetrating open ones, shear springs locked or sliding).
void add_contact_spring_energy(const std::vector<Contact>& contacts, double penalty,
                               double& energy);

// After an accepted step: each contact keeps its shear spring's energy for the next step's
// account (ContactState::spring_energy).
void record_spring_energies(std::vector<Contact>& contacts, double penalty);
// After an accepted step: each sliding contact's slip added to its slip_sum (what a
// slip-weakening joint's strength follows).
void record_slips(std::vector<Contact>& contacts);

// The deepest penetration of any contact after the step, as a share of that contact's
// allowed penetration (> 1: deeper than allowed); 0 if none.
double deepest_penetration_share(const std::vector<Contact>& contacts);

// The deepest penetration of any contact after the step (m); 0 if none.
double max_penetration(const std::vector<Contact>& contacts);

}  // namespace dda
