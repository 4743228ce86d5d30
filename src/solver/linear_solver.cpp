#include "solver/linear_solver.hpp"

namespace dda {

std::optional<Eigen::VectorXd> solve_dense(const BlockSystem& system) {
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(system.dense());
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return std::nullopt;
  return Eigen::VectorXd(ldlt.solve(system.rhs));
}

Eigen::VectorXd multiply(const BlockSystem& system, const Eigen::VectorXd& x) {
  Eigen::VectorXd y(x.size());
  for (int b = 0; b < system.block_rows(); ++b) {
    y.segment<6>(6 * b).noalias() = system.diagonal[b] * x.segment<6>(6 * b);
  }
  for (const BlockSystem::Coupling& c : system.couplings) {
    y.segment<6>(6 * c.row).noalias() += c.k * x.segment<6>(6 * c.col);
    y.segment<6>(6 * c.col).noalias() += c.k.transpose() * x.segment<6>(6 * c.row);
  }
  return y;
}

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
