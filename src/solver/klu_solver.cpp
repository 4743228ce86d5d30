// KLU for the unsymmetric step system (linear_solver.hpp). Only the solver room calls KLU.
#include <klu.h>

#include "solver/linear_solver.hpp"

namespace dda {

std::optional<Eigen::VectorXd> solve_klu(const BlockSystem& system) {
  Eigen::SparseMatrix<double> k = system.full();
  k.makeCompressed();
  const int n = static_cast<int>(k.rows());
  if (n == 0) return Eigen::VectorXd();
  klu_common common;
  klu_defaults(&common);
  int* ap = k.outerIndexPtr();
  int* ai = k.innerIndexPtr();
  klu_symbolic* symbolic = klu_analyze(n, ap, ai, &common);
  if (symbolic == nullptr) return std::nullopt;
  klu_numeric* numeric = klu_factor(ap, ai, k.valuePtr(), symbolic, &common);
  std::optional<Eigen::VectorXd> x;
  if (numeric != nullptr && common.status == KLU_OK) {
    Eigen::VectorXd b = system.rhs;
    if (klu_solve(symbolic, numeric, n, 1, b.data(), &common) == 1 && common.status == KLU_OK) {
      x = std::move(b);
    }
  }
  if (numeric != nullptr) klu_free_numeric(&numeric, &common);
  klu_free_symbolic(&symbolic, &common);
  return x;
}

}  // namespace dda
