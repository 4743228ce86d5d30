// Linear solves of the assembled system: CHOLMOD (the fast path, via Eigen's CholmodSupport)
// and a dense LDLT (the simple reference that tests compare it with).
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <optional>
#include <vector>

#include "solver/block_system.hpp"

namespace dda {

// Dense reference: LDLT of the whole matrix. nullopt when the matrix is not positive definite.
std::optional<Eigen::VectorXd> solve_dense(const BlockSystem& system);

// Sparse Cholesky with CHOLMOD. Keeps the symbolic analysis while the sparsity pattern is
// unchanged (a scene without contacts keeps it for the whole run).
class CholmodSolver {
 public:
  // Simplicial LL^T: it fails (rather than pivoting on) a matrix that is not positive
  // definite, which is how a broken system is detected.
  CholmodSolver() { factor_.setMode(Eigen::CholmodSimplicialLLt); }

  // nullopt when the factorisation fails (matrix not positive definite).
  std::optional<Eigen::VectorXd> solve(const BlockSystem& system);

 private:
  bool same_pattern(const Eigen::SparseMatrix<double>& k) const;

  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> factor_;
  std::vector<int> outer_;
  std::vector<int> inner_;
  bool analysed_ = false;
};

}  // namespace dda
