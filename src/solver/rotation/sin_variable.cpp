// sin_variable (Cheng and Zhang, paper Eqs. 9-12): T' carries the column (R(r) - I) / sin r
// at the last step's r0 (Eq. 11), fixed over the step, with sin r0 as the unknown in the
// rotation slot; points move by T' d' with the same T', strains added in the global frame.
#include <algorithm>
#include <cmath>

#include "kinematics/block_matrices.hpp"
#include "solver/rotation/moved_by_increments.hpp"
#include "solver/rotation/rotation_columns.hpp"

namespace dda {
namespace {

class SinVariable final : public MovedByIncrements {
 public:
  void start_step(const World& world, const StepContext& /*ctx*/, LoopTerms& terms,
                  RotationIterate& it) const override {
    it.angles = last_rotation_increments(world);
    set_rotation_columns(world, it.angles, sine_rotation_column, terms);
  }

  // The loop solved for sin r0 in the rotation slot; the stages after it want r0.
  void finish_unknowns(const World& world, Eigen::VectorXd& d) const override {
    for (const Block& b : world.blocks) {
      if (!b.fixed) d[b.first_dof + kR0] = std::asin(std::clamp(d[b.first_dof + kR0], -1.0, 1.0));
    }
  }

  // T' d' with d' = (u0, v0, sin r0, ex, ey, gxy) (d holds r0 = asin of the solved unknown).
  Vec2 displacement(const Block& b, const Vec2& offset, const Vec6& db) const override {
    Vec6 sine_db = db;
    sine_db[kR0] = std::sin(db[kR0]);
    return t_with_rotation_column(sine_rotation_column(b.last_rotation_increment)).at(offset) *
           sine_db;
  }
};

}  // namespace

const RotationTreatment& sin_variable_treatment() {
  static const SinVariable treatment;
  return treatment;
}

}  // namespace dda
