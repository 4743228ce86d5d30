// The global system K d = f in 6x6 blocks: one block row per free block. Symmetric, except
// that a plastic block with non-associated flow puts its unsymmetric consistent tangent into
// its own diagonal block; only the diagonal blocks (whole) and the couplings below the
// diagonal are stored. Assembly fills it; the linear solvers (dense reference, CHOLMOD for
// the symmetric system, KLU for the unsymmetric one) read it.
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

  std::vector<Mat6> diagonal;
  std::vector<Coupling> couplings;
  Eigen::VectorXd rhs;

  // Zero system of n block rows (6 n unknowns).
  void reset(int n);
  int block_rows() const { return static_cast<int>(diagonal.size()); }

  // The lower triangle as a compressed column matrix (what CHOLMOD reads).
  Eigen::SparseMatrix<double> lower_triangle() const;
  // The whole matrix as a compressed column matrix, diagonal blocks as stored (what KLU reads).
  Eigen::SparseMatrix<double> full() const;
  // The whole matrix, dense (the reference path in tests).
  Eigen::MatrixXd dense() const;
};

}  // namespace dda
