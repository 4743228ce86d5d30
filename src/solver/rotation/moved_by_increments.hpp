// The treatments that move every point by the step's increments, x += displacement(x - x0,
// d), and add the strain increments in the global frame (paper Eq. 13): original,
// second_order, post_adjustment, sin_variable. Each says only how a point at offset x - x0
// from the block's reference point moves.
#pragma once

#include "solver/rotation/treatment.hpp"

namespace dda {

class MovedByIncrements : public RotationTreatment {
 public:
  bool keeps_frame() const override { return false; }
  // No block-frame strain to carry the pseudo-rigid inertia: Shi's.
  Inertia auto_inertia() const override { return Inertia::Shi; }
  Vec2 vertex_after(const Block& b, std::size_t k, const Vec6& db,
                    const Mat2* column) const override;
  void move_blocks(World& world, const Eigen::VectorXd& d, const StepContext* ctx) const override;

  // The displacement of the point at `offset` from block b's reference point (at the step's
  // start) by the block's increments db.
  virtual Vec2 displacement(const Block& b, const Vec2& offset, const Vec6& db) const = 0;
};

}  // namespace dda
