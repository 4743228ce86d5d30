// Per-step settings, rebuilt for every attempt of a step (no globals), and the terms the
// contact loop changes as it iterates, kept apart from them.
#pragma once

#include <span>
#include <vector>

#include "kinematics/block_matrices.hpp"
#include "kinematics/rotating_inertia.hpp"
#include "solver/elements/bolt_law.hpp"
#include "solver/joint_water.hpp"

namespace dda {

// A plastic block's material linearised at a strain increment (global frame): the step
// equations use stress + tangent (de - strain_increment) for its stress at increment de.
struct MaterialLinearization {
  Vec3 strain_increment = Vec3::Zero();  // the step's strain increment it was taken at
  Vec3 stress = Vec3::Zero();            // (sxx, syy, sxy) there, Pa
  Mat3 tangent = Mat3::Zero();           // d stress / d strain increment (consistent)
  bool symmetric = true;                 // false for non-associated flow while yielding
};

// What the contact loop changes as it iterates towards an attempt's answer (solver/step.cpp):
// the blocks' T, the plastic blocks' linearisation and the rotating inertia's spins. The loop
// owns them and changes them only through functions that take them by reference; everything
// that builds the step's equations reads them through StepContext::loop.
struct LoopTerms {
  // Each block's T (by block index) for the treatments that change its rotation column
  // inside the step (sin_variable, finite_rotation), made once per change of the columns,
  // not at every contact that reads it. Empty: Shi's T for all.
  std::vector<LinearT> block_ts;
  // The plastic blocks' material linearisation (by block index) for the Newton iteration
  // nested in the open-close loop. Empty when the scene has no plastic block.
  std::vector<MaterialLinearization> material_terms;
  // The rotating-frame inertia (kinematics/rotating_inertia.hpp) of each deformable block
  // (by block index): the spin its quadratic velocity terms are taken at. Empty: no such
  // terms (Shi's inertia, or a static step).
  std::vector<Spin> spins;
  // Each bolt's mode (by bolt index; solver/elements/bolt_law.hpp): elastic or yielding,
  // followed after each solve like the plastic blocks' linearisation. Empty: no bolts.
  std::vector<BoltMode> bolt_modes;
};

// The settings of one attempt of a step: fixed from its start to its end.
struct StepContext {
  double dt = 0.0;                    // this attempt's time step (s)
  double penalty = 0.0;               // pin and contact normal stiffness (N/m)
  double dynamic_coefficient = 1.0;   // share of last velocity carried in, [0, 1]
  // Base shaking: the ground's mean acceleration over this attempt's step (m/s^2; zero
  // without base_motion). The step is solved in the ground's frame (solver/base_motion.hpp).
  Vec2 base_acceleration = Vec2::Zero();
  // The joint water's forces on the blocks (solver/joint_water.hpp), constant over the step
  // (from the contacts detected at its start); empty without water.
  std::span<const BlockForce> water_forces;
  // The contact loop's present terms (owned by the attempt, solver/step.cpp); null: none
  // (Shi's T for all, no rotating-frame spins, no plastic linearisation).
  const LoopTerms* loop = nullptr;
};

inline const std::vector<Spin>* loop_spins(const StepContext& ctx) {
  return ctx.loop != nullptr && !ctx.loop->spins.empty() ? &ctx.loop->spins : nullptr;
}
inline const std::vector<MaterialLinearization>* loop_material_terms(const StepContext& ctx) {
  return ctx.loop != nullptr && !ctx.loop->material_terms.empty() ? &ctx.loop->material_terms
                                                                  : nullptr;
}

// The T that this step uses for block `block` (everything that builds the step equations
// calls this: inertia, loads, pins, contacts).
inline const LinearT& step_t(const StepContext& ctx, int block) {
  if (ctx.loop == nullptr || ctx.loop->block_ts.empty()) return shi_t();
  return ctx.loop->block_ts[static_cast<std::size_t>(block)];
}

}  // namespace dda
