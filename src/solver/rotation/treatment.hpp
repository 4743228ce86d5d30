// The rotation treatments (paper Sections 2-4; the scene's control.rotation_update): each
// one is a RotationTreatment in a file of its own under solver/rotation/ and one line of the
// one table, treatments.def (its enum value, its scene name, the function that returns it). The step and the configuration update ask a
// treatment only through the verbs below, never which treatment it is.
//
// Two families share their rules (each a base class with a file of its own):
//   moved_by_increments: every point moved by the step's increments, strains added in the
//     global frame (Eq. 13): original, second_order, post_adjustment, sin_variable;
//   kept_in_block_frame: total strain, strain rates and stress kept in the block's own frame
//     (Section 3), every point placed from its material point at the start (Eq. 19):
//     local_frame, local_frame_as_printed, paper, and the secant family below it;
//   secant_column (within the second): T carries the secant rotation column at the step's
//     own r0, iterated with the contact loop: finite_rotation, finite_rotation_polar.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "kinematics/types.hpp"
#include "solver/block_system.hpp"
#include "solver/scene.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// What a treatment carries through one attempt's contact loop: the angle inside each block's
// rotation column of T, for the treatments that change T inside the step (empty otherwise).
struct RotationIterate {
  std::vector<double> angles;  // by block index
};

// What the contact loop tells a treatment about the solve it follows.
struct SolveFollow {
  bool spinning = false;     // the loop terms' spins hold the rotating inertia's spins (they follow too)
  bool check_spins = false;  // plastic blocks' spins are checked against their tolerance
  // Not null: blocks in flight whose angle is off may settle block by block with these
  // block terms (the converged solver, when no measure point moved and no block is plastic).
  BlockSystem* free_block_terms = nullptr;
};

// What following a solve did.
struct Followed {
  int moved = 0;                 // blocks whose T or spin is off the answer: solve again
  bool columns_changed = false;  // the loop's rotation columns were set anew
  // Blocks in flight settled block by block: d, the loop's T and spins and the block terms are
  // now those of the settled increments.
  bool settled_free_blocks = false;
};

class RotationTreatment {
 public:
  virtual ~RotationTreatment() = default;

  // ---- what the treatment keeps ----

  // Whether total strain, strain rates and stress are kept in the block's own frame (paper
  // Section 3) rather than strain increments added in the global frame (Eq. 13).
  virtual bool keeps_frame() const = 0;
  // The inertia control.inertia "auto" stands for (docs/rotating-inertia.md).
  virtual Inertia auto_inertia() const = 0;
  // Whether block b's step moves its present shape, F' = (I + r0 a + dE) F (the deformable
  // blocks of finite_rotation_polar): its strain unknowns are then increments of the spatial
  // velocity gradient's symmetric part, its local_strain a Hencky strain and its stress
  // Kirchhoff's over its initial area (docs/large-strain.md).
  virtual bool moves_present_shape(const Block&) const { return false; }

  // ---- the step (its contact loop, solver/step.cpp) ----

  // An attempt's start: T's rotation columns (terms.block_ts) for the treatments that change
  // T inside the step, and the angles inside them. Others leave Shi's T. (`terms` is the
  // loop's, which ctx.loop shows to everything that assembles: StepContext.)
  virtual void start_step(const World&, const StepContext&, LoopTerms& /*terms*/,
                          RotationIterate&) const {}
  // After a solve whose answer is d: T (and the rotating inertia's spins) follow the answer
  // where the treatment iterates them with the loop. Returns how many blocks were off.
  virtual Followed follow_solve(const World&, Eigen::VectorXd& /*d*/, const StepContext&,
                                LoopTerms& /*terms*/, RotationIterate&,
                                const SolveFollow&) const {
    return {};
  }
  // After the loop: the unknowns in d turned into (u0, v0, r0, ex, ey, gxy) where the
  // treatment solved for something else in a slot.
  virtual void finish_unknowns(const World&, Eigen::VectorXd& /*d*/) const {}

  // ---- the configuration update (solver/configuration_update.cpp) ----

  // Where vertex k of the free block b will be after move_blocks with increments db
  // (`column`: the rotation column of the block's T; null: the secant column at its r0).
  virtual Vec2 vertex_after(const Block& b, std::size_t k, const Vec6& db,
                            const Mat2* column) const = 0;
  // Moves vertices, pins, point loads and monitors, and accumulates translation, rotation
  // and strain, by the step's increments d (`ctx`: the step's T, or null).
  virtual void move_blocks(World& world, const Eigen::VectorXd& d,
                           const StepContext* ctx) const = 0;
  // Whether the free deformable block b, moved by db with its T's rotation column `column`,
  // ends with no positive area (also a nan): turned inside out.
  virtual bool turns_inside_out(const Block& b, const Vec6& db, const Mat2& column) const;
};

// The treatment of a scene's control.rotation_update (the table, treatment_table.cpp).
const RotationTreatment& treatment_for(RotationUpdate u);

inline const RotationTreatment& treatment_of(const World& world) {
  return treatment_for(world.control.rotation_update);
}

inline bool keeps_block_frame(RotationUpdate u) { return treatment_for(u).keeps_frame(); }

}  // namespace dda
