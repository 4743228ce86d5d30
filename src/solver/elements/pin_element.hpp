// Pins as a force element (solver/force_element.hpp): a penalty spring of the scene's
// stiffness p between a block's pinned material point and its anchor (Shi 1988, ch. 2). It
// adds p T^T T at the point and the pull towards the anchor to the system, loses the
// backward-Euler share p/2 |T d|^2 of a step, and stores p/2 |anchor - point|^2.
#pragma once

#include "solver/force_element.hpp"

namespace dda {

extern const ForceElement kPinElement;

}  // namespace dda
