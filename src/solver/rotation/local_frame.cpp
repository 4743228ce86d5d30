// local_frame (Jiang and Zheng, Sections 3-4): strain kept in the block frame, each step's
// increment turned into it by the mid-step angle, and x = xc + R(r)(I + E^)(X - Xc) (Eq. 19
// in the consistent form). All of it is kept_in_block_frame's rule.
#include "solver/rotation/kept_in_block_frame.hpp"

namespace dda {
namespace {

class LocalFrame final : public KeptInBlockFrame {};

}  // namespace

const RotationTreatment& local_frame_treatment() {
  static const LocalFrame treatment;
  return treatment;
}

}  // namespace dda
