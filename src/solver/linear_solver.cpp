#include "solver/linear_solver.hpp"

#include <algorithm>

namespace dda {

std::optional<Eigen::VectorXd> solve_dense(const BlockSystem& system) {
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(system.dense());
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return std::nullopt;
  return Eigen::VectorXd(ldlt.solve(system.rhs));
}

bool CholmodSolver::same_pattern(const Eigen::SparseMatrix<double>& k) const {
  if (!analysed_ || static_cast<int>(outer_.size()) != k.outerSize() + 1 ||
      static_cast<long>(inner_.size()) != k.nonZeros()) {
    return false;
  }
  return std::equal(outer_.begin(), outer_.end(), k.outerIndexPtr()) &&
         std::equal(inner_.begin(), inner_.end(), k.innerIndexPtr());
}

std::optional<Eigen::VectorXd> CholmodSolver::solve(const BlockSystem& system) {
  Eigen::SparseMatrix<double> k = system.lower_triangle();
  k.makeCompressed();
  if (!same_pattern(k)) {
    factor_.analyzePattern(k);
    outer_.assign(k.outerIndexPtr(), k.outerIndexPtr() + k.outerSize() + 1);
    inner_.assign(k.innerIndexPtr(), k.innerIndexPtr() + k.nonZeros());
    analysed_ = true;
  }
  factor_.factorize(k);
  if (factor_.info() != Eigen::Success) return std::nullopt;
  Eigen::VectorXd x = factor_.solve(system.rhs);
  if (factor_.info() != Eigen::Success) return std::nullopt;
  return x;
}

}  // namespace dda
