// paper: the paper's method as printed (Sections 3-4), for reproducing its tables:
// local_frame with each step's strain increment turned into the block frame by the
// end-of-step angle r + r0 (Eq. 17, its sign corrected) instead of the mid-step angle, and
// Shi's inertia unless control.inertia asks for another (the paper keeps Shi's mass matrix).
#include "kinematics/frames.hpp"
#include "solver/rotation/kept_in_block_frame.hpp"

namespace dda {
namespace {

class Paper final : public KeptInBlockFrame {
 public:
  Inertia auto_inertia() const override { return Inertia::Shi; }
  // The update has advanced b.rotation to the end angle.
  Vec3 increment_in_frame(const Block& b, const Vec6& db) const override {
    return strain_in_turned_frame(db.segment<3>(kEx), b.rotation);
  }
  Vec3 block_frame_increment(const Block& b, const Vec6& db, const Mat2*) const override {
    return strain_in_turned_frame(db.segment<3>(kEx), b.rotation + db[kR0]);
  }
};

}  // namespace

const RotationTreatment& paper_treatment() {
  static const Paper treatment;
  return treatment;
}

}  // namespace dda
