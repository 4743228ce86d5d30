// The one place where the step's system meets the linear solvers (rigid
// blocks). The system is assembled with six slots per block row; with rigid blocks the
// solvers see only the unknowns of its dof map (BlockSystem: a rigid block's u0, v0, r0), so
// the rhs and, for an update of the factor, the springs that changed are reduced to them
// here, and the answer is expanded back to six slots per block, a rigid block's strain
// increments exactly zero. Without rigid blocks the two layouts are the same and nothing is
// copied.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "solver/block_system.hpp"
#include "solver/sparse_cholesky.hpp"
#include "solver/step.hpp"

namespace dda {

// Which solver: KLU (an unsymmetric system), a CHOLMOD factorisation, or CHOLMOD's last
// factor updated by ws.springs_added and ws.springs_removed (CholmodSolver::solve_modified).
enum class SolvePath { Klu, Factorise, Modify };

// Solves ws.system (rhs in six slots per block row, as assembled; reduced in place) by
// `path`; the answer in six slots per block, nullopt when the solver fails.
std::optional<Eigen::VectorXd> solve_system(StepWorkspace& ws, SolvePath path);

// Each term c c^T restricted to the system's unknowns: a rigid block's strain slots dropped
// from c, the rest renumbered (the spring acting with those increments held at zero).
void reduce_terms(const BlockSystem& system, std::vector<RankOneTerm>& terms);

}  // namespace dda
