#include "solver/linear_solver.hpp"

namespace dda {

std::optional<Eigen::VectorXd> solve_dense(const BlockSystem& system) {
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(system.dense());
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return std::nullopt;
  return Eigen::VectorXd(ldlt.solve(system.rhs));
}

// ---- rigid blocks (issue 10, item 7): x and y in the dof map's reduced layout; each block
// acts by its leading unknowns_of(row) x unknowns_of(col) corner (BlockSystem) ----
Eigen::VectorXd multiply(const BlockSystem& system, const Eigen::VectorXd& x) {
  const std::vector<int>& o = system.offset;
  Eigen::VectorXd y(x.size());
  for (int b = 0; b < system.block_rows(); ++b) {
    const int u = system.unknowns_of(b);
    y.segment(o[b], u).noalias() = system.diagonal[b].topLeftCorner(u, u) * x.segment(o[b], u);
  }
  for (const BlockSystem::Coupling& c : system.couplings) {
    const int ur = system.unknowns_of(c.row), uc = system.unknowns_of(c.col);
    y.segment(o[c.row], ur).noalias() += c.k.topLeftCorner(ur, uc) * x.segment(o[c.col], uc);
    y.segment(o[c.col], uc).noalias() +=
        c.k.topLeftCorner(ur, uc).transpose() * x.segment(o[c.row], ur);
  }
  return y;
}
// ---- end rigid blocks ----

std::vector<std::pair<int, int>> CholmodSolver::block_pattern(const BlockSystem& system) const {
  std::vector<std::pair<int, int>> pattern;
  pattern.reserve(system.couplings.size());
  for (const BlockSystem::Coupling& c : system.couplings) pattern.emplace_back(c.row, c.col);
  return pattern;
}

std::optional<Eigen::VectorXd> CholmodSolver::solve(const BlockSystem& system) {
  Eigen::SparseMatrix<double> k = system.lower_triangle();
  k.makeCompressed();
  ++factorisations_;
  factored_rows_ = -1;
  if (!factor_.factorize(k)) return std::nullopt;
  factored_blocks_ = block_pattern(system);
  factored_rows_ = system.block_rows();
  return factor_.solve(system.rhs);
}

std::optional<Eigen::VectorXd> CholmodSolver::solve_modified(const BlockSystem& system,
                                                             const std::vector<RankOneTerm>& added,
                                                             const std::vector<RankOneTerm>& removed) {
  if (!factor_.has_factor() || system.block_rows() != factored_rows_ ||
      block_pattern(system) != factored_blocks_) {
    return solve(system);
  }
  if (factor_.modification_cost(added) + factor_.modification_cost(removed) >
      kModifyShareOfRefactor * factor_.refactorisation_cost()) {
    return solve(system);
  }
  ++modifications_;
  // Updates first: the matrix stays positive definite all along.
  if (!factor_.modify(added, true) || !factor_.modify(removed, false)) return solve(system);
  Eigen::VectorXd x = factor_.solve(system.rhs);
  const double residual = (multiply(system, x) - system.rhs).norm();
  if (!(residual <= kModifiedResidualTolerance * system.rhs.norm())) return solve(system);
  return x;
}

}  // namespace dda
