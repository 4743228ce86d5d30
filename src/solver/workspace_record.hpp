// What a checkpoint keeps of the step loop's workspace (StepWorkspace, solver/step.hpp), so
// that a run continued from it takes the steps of the run never stopped, bit for bit: the
// linear solver's kept factor with its refresh counters (CholmodSolver::Record) and the
// ledger of the contact springs that factor holds (FactorSprings). Everything else in the
// workspace is a buffer remade on use, or the detection cache's carried pairs, which are
// checked against the world on every call and give the same pairs whatever they hold.
#pragma once

#include <vector>

#include "solver/factor_springs.hpp"
#include "solver/linear_solver.hpp"
#include "solver/step.hpp"

namespace dda {

struct WorkspaceRecord {
  CholmodSolver::Record solver;
  std::vector<FactorSprings::Entry> factor_springs;
};

WorkspaceRecord record_workspace(const StepWorkspace& ws);

// Puts the record into `ws`. False when the factor could not be rebuilt (see
// CholmodSolver::restore): the workspace then starts without one and its ledger empty, as a
// new run's does, and the run continues exactly but for round-off.
bool restore_workspace(StepWorkspace& ws, const WorkspaceRecord& record);

}  // namespace dda
