// finite_rotation: local_frame's update, the step solved with T's secant rotation column at
// an angle that follows the step's own r0 (secant_column.hpp).
#include "solver/rotation/secant_column.hpp"

namespace dda {
namespace {

class FiniteRotation final : public SecantColumn {};

}  // namespace

const RotationTreatment& finite_rotation_treatment() {
  static const FiniteRotation treatment;
  return treatment;
}

}  // namespace dda
