// second_order (MacLaughlin and Sitar): points moved by paper Eq. 8 with cos r0 = 1 - r0^2/2
// and sin r0 = r0, strains added in the global frame.
#include "kinematics/point_maps.hpp"
#include "solver/rotation/moved_by_increments.hpp"

namespace dda {
namespace {

class SecondOrder final : public MovedByIncrements {
 public:
  Vec2 displacement(const Block&, const Vec2& offset, const Vec6& db) const override {
    return second_order_displacement(offset, db);
  }
};

}  // namespace

const RotationTreatment& second_order_treatment() {
  static const SecondOrder treatment;
  return treatment;
}

}  // namespace dda
