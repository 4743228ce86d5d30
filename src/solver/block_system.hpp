// The global system K d = f in 6x6 blocks: one block row per free block. Symmetric; only
// the diagonal blocks and the couplings below the diagonal are stored. Assembly fills it;
// the linear solvers (dense reference, CHOLMOD) read it.
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
  // The whole symmetric matrix, dense (the reference path in tests).
  Eigen::MatrixXd dense() const;
};

}  // namespace dda
