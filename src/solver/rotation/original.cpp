// original (Shi 1988): every point moved by T d with Shi's first-order T (paper Eq. 2),
// strains added in the global frame (Eq. 13).
#include "kinematics/block_matrices.hpp"
#include "solver/rotation/moved_by_increments.hpp"

namespace dda {
namespace {

class Original final : public MovedByIncrements {
 public:
  Vec2 displacement(const Block&, const Vec2& offset, const Vec6& db) const override {
    return Vec2(shi_t().at(offset) * db);
  }
};

}  // namespace

const RotationTreatment& original_treatment() {
  static const Original treatment;
  return treatment;
}

}  // namespace dda
