// Per-step settings, rebuilt for every attempt of a step (no globals).
#pragma once

#include <vector>

#include "kinematics/block_matrices.hpp"

namespace dda {

struct StepContext {
  double dt = 0.0;                    // this attempt's time step (s)
  double penalty = 0.0;               // pin and contact normal stiffness (N/m)
  double dynamic_coefficient = 1.0;   // share of last velocity carried in, [0, 1]
  double allowed_displacement = 0.0;  // max_displacement_ratio * w0 (m)
  // The rotation column of T for each block (by block index), for the treatments that
  // change T inside the step (sin_variable, finite_rotation). Empty: Shi's column for all.
  std::vector<Mat2> rotation_columns;
};

// The T that this step uses for block `block` (everything that builds the step equations
// calls this: inertia, loads, pins, contacts).
inline LinearT step_t(const StepContext& ctx, int block) {
  if (ctx.rotation_columns.empty()) return shi_t();
  return t_with_rotation_column(ctx.rotation_columns[static_cast<std::size_t>(block)]);
}

}  // namespace dda
