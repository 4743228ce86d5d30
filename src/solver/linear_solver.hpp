// Linear solves of the assembled system: CHOLMOD (the fast path) and a dense LDLT (the simple
// reference that tests compare it with).
#pragma once

#include <Eigen/Sparse>
#include <optional>
#include <utility>
#include <vector>

#include "solver/block_system.hpp"
#include "solver/sparse_cholesky.hpp"

namespace dda {

// Dense reference: LDLT of the whole matrix. nullopt when the matrix is not positive definite.
std::optional<Eigen::VectorXd> solve_dense(const BlockSystem& system);

// Sparse LU with KLU for the unsymmetric system (a non-associated plastic block's tangent):
// analysed and factorised at every call. nullopt when the matrix is singular.
std::optional<Eigen::VectorXd> solve_klu(const BlockSystem& system);

// y = K x for the symmetric block system (diagonal blocks plus couplings both ways), x and
// y in the reduced layout of its dof map (BlockSystem: a rigid block's strain slots dropped).
Eigen::VectorXd multiply(const BlockSystem& system, const Eigen::VectorXd& x);

// Sparse LDL' with CHOLMOD.
//  - solve(): factorise and solve; the symbolic analysis is kept while the sparsity pattern
//    is unchanged (a scene without contacts keeps it for the whole run).
//  - solve_modified(): the system differs from the one last factorised only by the springs
//    of contacts that changed mode (`added` now present, `removed` gone): the factor is
//    updated and downdated in place (rank one per spring) instead of refactorised. The
//    answer is checked against the assembled system and refactorised if it falls short.
class CholmodSolver {
 public:
  // nullopt when the matrix is not positive definite.
  std::optional<Eigen::VectorXd> solve(const BlockSystem& system);
  std::optional<Eigen::VectorXd> solve_modified(const BlockSystem& system,
                                                const std::vector<RankOneTerm>& added,
                                                const std::vector<RankOneTerm>& removed);

  // solve_modified refactorises instead when the modification's modelled cost
  // (SparseCholesky::modification_cost) exceeds this share of a refactorisation's
  // (refactorisation_cost). Measured on the 1000-brick wall, pinned to one core: while it
  // settles (5 to 8 solves a step, tens of changed springs each), 668 ms a step updating
  // always, 246 ms at share 0.1 (refactorising at nearly every iteration; 29 ms each); the
  // settled wall (1.2 solves) 49 to 51 ms either way. An updated entry costs far more than a
  // factorisation's multiply-add (cholmod_updown revisits each column once per term).
  static constexpr double kModifyShareOfRefactor = 0.1;

  // A modified factor's answer must leave a residual below this share of |rhs|; a fresh
  // factorisation leaves ~1e-16 x condition, so 1e-9 only catches a factor gone astray.
  static constexpr double kModifiedResidualTolerance = 1e-9;

  int factorisations() const { return factorisations_; }
  int modifications() const { return modifications_; }

 private:
  std::vector<std::pair<int, int>> block_pattern(const BlockSystem& system) const;

  SparseCholesky factor_;
  std::vector<std::pair<int, int>> factored_blocks_;  // couplings of the factorised system
  int factored_rows_ = -1;
  int factorisations_ = 0;
  int modifications_ = 0;
};

}  // namespace dda
