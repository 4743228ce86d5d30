// Rock bolts and cables as a force element (solver/force_element.hpp): an axial bar between
// two material points of two blocks (a fixed block is the ground it is anchored in), with
// the elastic-perfectly plastic law of bolt_law.hpp and a rupture at a plastic extension.
// Over a step its extension is dl = e . (T_b d_b - T_a d_a), e the unit vector from end a
// to end b at the step's start, and its energy N0 dl + k dl^2 / 2 while elastic (force
// N0 + k dl at the step's end) or +-N_y dl while yielding: it adds k g g^T and -N g to the
// system, g the gradient of dl. Its mode (elastic or yielding) is the loop's to follow, as
// the plastic blocks' linearisation is; it books the integration's loss and its plastic work
// (and a broken bar's spring energy, released as it breaks) and stores N^2 / 2k.
#pragma once

#include "solver/force_element.hpp"

namespace dda {

extern const ForceElement kBoltElement;

}  // namespace dda
