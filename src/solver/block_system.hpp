// The global system K d = f in 6x6 blocks: one block row per free block. Symmetric, except
// that a plastic block with non-associated flow puts its unsymmetric consistent tangent into
// its own diagonal block; only the diagonal blocks (whole) and the couplings below the
// diagonal are stored. Assembly fills it; the linear solvers (dense reference, CHOLMOD for
// the symmetric system, KLU for the unsymmetric one) read it.
//
// The dof map: a rigid block's row is assembled as 6x6 like any other,
// but only its u0, v0, r0 are unknowns of the system the solvers see. kU0, kV0, kR0 lead
// the six, so block row b's unknowns are simply its first unknowns_of(b) slots (6, or 3 if
// rigid), numbered from offset[b] in the reduced system. The matrices formed for the
// solvers (lower_triangle, full, dense; multiply in linear_solver.cpp) keep only those rows
// and columns. Dropping a rigid block's strain rows and columns is solving the six-slot
// system with its strain increments constrained to zero; the strain rows' residual is the
// force the rigidity carries, which nothing needs. The rest of the code keeps the six slots
// per block: reduce() and expand() translate at the solve (step_solve.hpp, solve_system).
#pragma once

#include <Eigen/Sparse>
#include <vector>

#include "kinematics/types.hpp"

namespace dda {

struct BlockSystem {
  struct Coupling {
    int row = 0;  // block row, row > col
    int col = 0;
    Mat6 k = Mat6::Zero();
  };

  // A rigid block's unknowns: u0, v0, r0.
  static constexpr int kRigidUnknowns = 3;

  std::vector<Mat6> diagonal;
  std::vector<Coupling> couplings;
  // Six slots per block row as assembled. The solvers read it as given: with rigid rows the
  // caller first puts it in the reduced layout (rhs = reduce(rhs)).
  Eigen::VectorXd rhs;
  // The dof map: block row b's unknowns are offset[b] .. offset[b + 1] - 1 (size n + 1).
  std::vector<int> offset{0};

  // Zero system of n deformable block rows (6 n unknowns).
  void reset(int n);
  // Zero system with one block row per entry of `rigid` (3 unknowns where true, else 6).
  void reset(const std::vector<bool>& rigid);
  int block_rows() const { return static_cast<int>(diagonal.size()); }

  int unknowns_of(int b) const { return offset[b + 1] - offset[b]; }
  int unknowns() const { return offset.back(); }
  // True when some block row is rigid (the solvers' system is smaller than 6 n).
  bool reduced() const { return unknowns() != 6 * block_rows(); }
  // The reduced index of six-slot index `slot` (6 b + k), or -1 when it is a rigid block's
  // strain slot, which is no unknown.
  int reduced_index(int slot) const;
  // Six slots per block row -> the solvers' unknowns (a rigid row's strain slots dropped).
  Eigen::VectorXd reduce(const Eigen::VectorXd& slots) const;
  // The solvers' unknowns -> six slots per block row, a rigid row's strain slots zero.
  Eigen::VectorXd expand(const Eigen::VectorXd& unknowns) const;

  // The lower triangle as a compressed column matrix (what CHOLMOD reads).
  Eigen::SparseMatrix<double> lower_triangle() const;
  // The whole matrix as a compressed column matrix, diagonal blocks as stored (what KLU reads).
  Eigen::SparseMatrix<double> full() const;
  // The whole matrix, dense (the reference path in tests).
  Eigen::MatrixXd dense() const;
};

}  // namespace dda
