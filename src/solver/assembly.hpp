// Stage "assemble": the global system of one DDA step (Shi 1988), block by block.
// For each free block with unknowns d (increments of u0, v0, r0, ex, ey, gxy):
//   (area D + 2/dt^2 M + springs) d = rho int T^T g + loads - area s + 2/dt M v0 + spring pulls
// where M = int rho T^T T and v0 = dynamic_coefficient * (last end-of-step velocity):
// Shi's scheme a = 2/dt^2 d - 2/dt v0 (Newmark beta = 1/2, gamma = 1).
#pragma once

#include "solver/block_system.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

void assemble(const World& world, const StepContext& ctx, BlockSystem& system);

}  // namespace dda
