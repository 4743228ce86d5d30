#include "solver/workspace_record.hpp"

namespace dda {

WorkspaceRecord record_workspace(const StepWorkspace& ws) {
  return WorkspaceRecord{ws.solver.record(), ws.factor_springs.entries()};
}

bool restore_workspace(StepWorkspace& ws, const WorkspaceRecord& record) {
  if (ws.solver.restore(record.solver)) {
    ws.factor_springs.restore(record.factor_springs);
    return true;
  }
  ws.factor_springs.clear();  // no factor, no springs in it
  return false;
}

}  // namespace dda
