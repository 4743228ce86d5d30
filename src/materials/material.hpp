// The material interface (MFront's behaviour data): state at the start of a step and total
// strain at its end in, stress, new state, consistent tangent and a status out
// (materials/material_types.hpp). integrate() is the switch over the models: it calls the
// returns (return_*.hpp), which know only the vocabulary, never this switch.
#pragma once

#include "kinematics/types.hpp"
#include "materials/material_types.hpp"

namespace dda {

// The stress of `params` at total strain (exx, eyy, gxy) from `start`, with initial stress
// s0 (sxx, syy, szz, sxy) (plane stress: its szz is ignored). Does not validate `params`
// (validate_material does, at input).
MaterialResult integrate(const MaterialParameters& params, const MaterialState& start,
                         const Vec3& total_strain, const Vec4& initial_stress = Vec4::Zero());

}  // namespace dda
