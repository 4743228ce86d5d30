#include "solver/step_solve.hpp"

#include "solver/linear_solver.hpp"

namespace dda {

void reduce_terms(const BlockSystem& system, std::vector<RankOneTerm>& terms) {
  for (RankOneTerm& term : terms) {
    std::size_t kept = 0;
    for (std::size_t e = 0; e < term.entries.size(); ++e) {
      const int unknown = system.reduced_index(term.entries[e].first);
      if (unknown >= 0) term.entries[kept++] = {unknown, term.entries[e].second};
    }
    term.entries.resize(kept);
  }
}

std::optional<Eigen::VectorXd> solve_system(StepWorkspace& ws, SolvePath path) {
  BlockSystem& system = ws.system;
  // A scene of fixed blocks only has nothing to solve for: every step moves nothing.
  if (system.unknowns() == 0) return Eigen::VectorXd(Eigen::VectorXd::Zero(6 * system.block_rows()));
  const bool reduced = system.reduced();
  if (reduced) {
    system.rhs = system.reduce(system.rhs);
    if (path == SolvePath::Modify) {
      reduce_terms(system, ws.springs_added);
      reduce_terms(system, ws.springs_removed);
    }
  }
  std::optional<Eigen::VectorXd> x;
  switch (path) {
    case SolvePath::Klu: x = solve_klu(system); break;
    case SolvePath::Factorise: x = ws.solver.solve(system); break;
    case SolvePath::Modify:
      x = ws.solver.solve_modified(system, ws.springs_added, ws.springs_removed);
      break;
  }
  if (reduced && x) *x = system.expand(*x);
  return x;
}

}  // namespace dda
