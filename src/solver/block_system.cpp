#include "solver/block_system.hpp"

namespace dda {

void BlockSystem::reset(int n) {
  diagonal.assign(n, Mat6::Zero());
  couplings.clear();
  rhs = Eigen::VectorXd::Zero(6 * n);
}

Eigen::SparseMatrix<double> BlockSystem::lower_triangle() const {
  const int n = 6 * block_rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(21 * diagonal.size() + 36 * couplings.size());
  for (int b = 0; b < block_rows(); ++b) {
    for (int j = 0; j < 6; ++j) {
      for (int i = j; i < 6; ++i) entries.emplace_back(6 * b + i, 6 * b + j, diagonal[b](i, j));
    }
  }
  for (const Coupling& c : couplings) {
    for (int j = 0; j < 6; ++j) {
      for (int i = 0; i < 6; ++i) entries.emplace_back(6 * c.row + i, 6 * c.col + j, c.k(i, j));
    }
  }
  Eigen::SparseMatrix<double> lower(n, n);
  lower.setFromTriplets(entries.begin(), entries.end());  // sums duplicate couplings
  return lower;
}

Eigen::SparseMatrix<double> BlockSystem::full() const {
  const int n = 6 * block_rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(36 * (diagonal.size() + 2 * couplings.size()));
  for (int b = 0; b < block_rows(); ++b) {
    for (int j = 0; j < 6; ++j) {
      for (int i = 0; i < 6; ++i) entries.emplace_back(6 * b + i, 6 * b + j, diagonal[b](i, j));
    }
  }
  for (const Coupling& c : couplings) {
    for (int j = 0; j < 6; ++j) {
      for (int i = 0; i < 6; ++i) {
        entries.emplace_back(6 * c.row + i, 6 * c.col + j, c.k(i, j));
        entries.emplace_back(6 * c.col + j, 6 * c.row + i, c.k(i, j));
      }
    }
  }
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(entries.begin(), entries.end());  // sums duplicate couplings
  return k;
}

Eigen::MatrixXd BlockSystem::dense() const {
  const int n = 6 * block_rows();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (int b = 0; b < block_rows(); ++b) k.block<6, 6>(6 * b, 6 * b) = diagonal[b];
  for (const Coupling& c : couplings) {
    k.block<6, 6>(6 * c.row, 6 * c.col) += c.k;
    k.block<6, 6>(6 * c.col, 6 * c.row) += c.k.transpose();
  }
  return k;
}

}  // namespace dda
