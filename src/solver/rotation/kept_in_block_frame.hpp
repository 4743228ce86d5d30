// The treatments that keep total strain, strain rates and stress in the block's own frame
// (paper Sections 3 and 4): translation, rotation (Eqs. 14, 15) and block-frame strain
// (Eqs. 16, 17) accumulated, every point placed from its material point at the start by
// x = xc + A (X - Xc) (Eq. 19). local_frame, local_frame_as_printed, paper, and the secant
// family (secant_column.hpp). Each says how the step's strain increment enters the block
// frame and what A is.
#pragma once

#include "solver/rotation/treatment.hpp"

namespace dda {

// The step's strain increment db[ex, ey, gxy] (global frame) in block b's frame, turned by
// the mid-step angle b.rotation + r0 / 2, for a block not yet updated (the update takes the
// same angle from its updated rotation).
Vec3 block_frame_increment(const Block& b, const Vec6& db);

class KeptInBlockFrame : public RotationTreatment {
 public:
  bool keeps_frame() const override { return true; }
  // The pseudo-rigid body's inertia, which the block-frame strain carries.
  Inertia auto_inertia() const override { return Inertia::PseudoRigid; }
  Vec2 vertex_after(const Block& b, std::size_t k, const Vec6& db,
                    const Mat2* column) const override;
  void move_blocks(World& world, const Eigen::VectorXd& d, const StepContext* ctx) const override;

  // The linear part A of the block's map from its initial configuration, from its total
  // rotation r and block-frame strain e^ (Eq. 19 in the consistent form: R(r)(I + E^)).
  virtual Mat2 map_from_initial(double r, const Vec3& local_strain) const;
  // The step's strain increment in the block frame (Eq. 17, sign corrected) for block b
  // whose rotation the update has advanced by r0: at the mid-step angle.
  virtual Vec3 increment_in_frame(const Block& b, const Vec6& db) const;
  // The same for a block not yet updated (vertex_after's, the spins'): block_frame_increment.
  // (`column`: the rotation column of the block's T; null: the secant column at its r0.)
  virtual Vec3 block_frame_increment(const Block& b, const Vec6& db, const Mat2* column) const;
  // Advances the free block b (its translation already moved by the step) by increments db:
  // its rotation, block-frame strain (and last_local_increment) and global strain. Returns
  // the map A that places its points. `ctx`: the step's T (null: none), `index` b's index.
  virtual Mat2 advance_block(Block& b, const Vec6& db, const StepContext* ctx, int index) const;
};

}  // namespace dda
