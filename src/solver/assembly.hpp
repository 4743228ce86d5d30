// Stage "assemble": the global system of one DDA step (Shi 1988), block by block.
// For each free block with unknowns d (increments of u0, v0, r0, ex, ey, gxy):
//   (area D + 2/dt^2 M + springs) d = rho int T^T g + loads - area s + 2/dt M v0 + spring pulls
// where M = int rho T^T T and v0 = dynamic_coefficient * (last end-of-step velocity):
// Shi's scheme a = 2/dt^2 d - 2/dt v0 (Newmark beta = 1/2, gamma = 1).
#pragma once

#include <vector>

#include "solver/block_system.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// A rigid block (Block::rigid) gets the same 6x6 terms less its strain terms (stiffness and
// stress: it has neither); its block row is marked rigid in the system's dof map, so that
// the solvers see only its u0, v0, r0 and the mass matrix acts through its top-left 3x3,
// diag(m, m, J) with Shi's T about the centroid (the rigid body's own).
void assemble(const World& world, const StepContext& ctx, BlockSystem& system);

// Per block row of the global system (free blocks in dof order): whether the block is rigid.
std::vector<bool> rigid_rows(const World& world);

}  // namespace dda
