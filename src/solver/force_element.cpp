#include "solver/force_element.hpp"

#include "solver/elements/block_element.hpp"
#include "solver/elements/pin_element.hpp"
#include "solver/elements/point_force_element.hpp"

namespace dda {

std::span<const ForceElement> force_elements() {
  // The order is the sums' order: assembly, work and stored energy are added up element by
  // element in it, so a change of order changes results in the last bits.
  static const ForceElement table[] = {kBlockElement, kPinElement, kPointForceElement};
  return table;
}

}  // namespace dda
