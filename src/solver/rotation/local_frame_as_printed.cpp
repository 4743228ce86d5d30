// local_frame_as_printed: local_frame with Eq. 19 as printed, the global total strain on
// the initial offsets, x = xc + (R + R E^ R^T)(X - Xc) (docs/paper-errata.md, item 2).
#include "kinematics/point_maps.hpp"
#include "solver/rotation/kept_in_block_frame.hpp"

namespace dda {
namespace {

class LocalFrameAsPrinted final : public KeptInBlockFrame {
 public:
  Mat2 map_from_initial(double r, const Vec3& local_strain) const override {
    return frame_map_as_printed(r, local_strain);
  }
};

}  // namespace

const RotationTreatment& local_frame_as_printed_treatment() {
  static const LocalFrameAsPrinted treatment;
  return treatment;
}

}  // namespace dda
