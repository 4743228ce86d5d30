// Point loads and joint water as a force element (solver/force_element.hpp): forces at
// material points of the blocks, constant over a step (a point load as the scene gives it,
// the water's resultant on each wetted face as the step's start sets it). Each adds T^T F
// to the right-hand side and books F . (T d) as load work; neither stores energy.
#pragma once

#include "solver/force_element.hpp"

namespace dda {

extern const ForceElement kPointForceElement;

}  // namespace dda
