// T's rotation column for the treatments that change it inside the step (sin_variable,
// finite_rotation, finite_rotation_polar): the loop's block_ts set from one angle per block.
#pragma once

#include <vector>

#include "kinematics/types.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// Each block's r0 of the last step (the angle the step's columns start from).
std::vector<double> last_rotation_increments(const World& world);

// terms.block_ts: Shi's T for fixed blocks; for every other block T with the rotation column
// column(angles[i]) (secant_rotation_column or sine_rotation_column,
// kinematics/block_matrices.hpp).
void set_rotation_columns(const World& world, const std::vector<double>& angles,
                          Mat2 (*column)(double), LoopTerms& terms);

// The rotation column block `index` was solved with: that of ctx's T; without ctx, the
// secant column at r0.
Mat2 solved_rotation_column(const StepContext* ctx, int index, double r0);

}  // namespace dda
