// post_adjustment (Ke; Koo and Chern): the step solved with Shi's T, then points moved by
// paper Eq. 8 with the exact cos r0 and sin r0; strains added in the global frame.
#include "kinematics/point_maps.hpp"
#include "solver/rotation/moved_by_increments.hpp"

namespace dda {
namespace {

class PostAdjustment final : public MovedByIncrements {
 public:
  Vec2 displacement(const Block&, const Vec2& offset, const Vec6& db) const override {
    return finite_rotation_displacement(offset, db);
  }
};

}  // namespace

const RotationTreatment& post_adjustment_treatment() {
  static const PostAdjustment treatment;
  return treatment;
}

}  // namespace dda
