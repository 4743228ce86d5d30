#include "solver/block_system.hpp"

#include <cassert>

namespace dda {

void BlockSystem::reset(int n) { reset(std::vector<bool>(static_cast<std::size_t>(n), false)); }

void BlockSystem::reset(const std::vector<bool>& rigid) {
  const int n = static_cast<int>(rigid.size());
  diagonal.assign(n, Mat6::Zero());
  couplings.clear();
  rhs = Eigen::VectorXd::Zero(6 * n);
  offset.assign(n + 1, 0);
  for (int b = 0; b < n; ++b) offset[b + 1] = offset[b] + (rigid[b] ? kRigidUnknowns : 6);
}

int BlockSystem::reduced_index(int slot) const {
  const int b = slot / 6, k = slot % 6;
  return k < unknowns_of(b) ? offset[b] + k : -1;
}

Eigen::VectorXd BlockSystem::reduce(const Eigen::VectorXd& slots) const {
  assert(slots.size() == 6 * block_rows());
  Eigen::VectorXd out(unknowns());
  for (int b = 0; b < block_rows(); ++b) {
    out.segment(offset[b], unknowns_of(b)) = slots.segment(6 * b, unknowns_of(b));
  }
  return out;
}

Eigen::VectorXd BlockSystem::expand(const Eigen::VectorXd& unknowns) const {
  assert(unknowns.size() == this->unknowns());
  Eigen::VectorXd out = Eigen::VectorXd::Zero(6 * block_rows());
  for (int b = 0; b < block_rows(); ++b) {
    out.segment(6 * b, unknowns_of(b)) = unknowns.segment(offset[b], unknowns_of(b));
  }
  return out;
}

// Each 6x6 block enters with its leading unknowns_of(row) x unknowns_of(col) corner at
// (offset[row], offset[col]): the dof map.
Eigen::SparseMatrix<double> BlockSystem::lower_triangle() const {
  const int n = unknowns();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(21 * diagonal.size() + 36 * couplings.size());
  for (int b = 0; b < block_rows(); ++b) {
    const int o = offset[b], u = unknowns_of(b);
    for (int j = 0; j < u; ++j) {
      for (int i = j; i < u; ++i) entries.emplace_back(o + i, o + j, diagonal[b](i, j));
    }
  }
  for (const Coupling& c : couplings) {
    const int ur = unknowns_of(c.row), uc = unknowns_of(c.col);
    for (int j = 0; j < uc; ++j) {
      for (int i = 0; i < ur; ++i) {
        entries.emplace_back(offset[c.row] + i, offset[c.col] + j, c.k(i, j));
      }
    }
  }
  Eigen::SparseMatrix<double> lower(n, n);
  lower.setFromTriplets(entries.begin(), entries.end());  // sums duplicate couplings
  return lower;
}

Eigen::SparseMatrix<double> BlockSystem::full() const {
  const int n = unknowns();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(36 * (diagonal.size() + 2 * couplings.size()));
  for (int b = 0; b < block_rows(); ++b) {
    const int o = offset[b], u = unknowns_of(b);
    for (int j = 0; j < u; ++j) {
      for (int i = 0; i < u; ++i) entries.emplace_back(o + i, o + j, diagonal[b](i, j));
    }
  }
  for (const Coupling& c : couplings) {
    const int ur = unknowns_of(c.row), uc = unknowns_of(c.col);
    const int orow = offset[c.row], ocol = offset[c.col];
    for (int j = 0; j < uc; ++j) {
      for (int i = 0; i < ur; ++i) {
        entries.emplace_back(orow + i, ocol + j, c.k(i, j));
        entries.emplace_back(ocol + j, orow + i, c.k(i, j));
      }
    }
  }
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(entries.begin(), entries.end());  // sums duplicate couplings
  return k;
}

Eigen::MatrixXd BlockSystem::dense() const {
  const int n = unknowns();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (int b = 0; b < block_rows(); ++b) {
    const int u = unknowns_of(b);
    k.block(offset[b], offset[b], u, u) = diagonal[b].topLeftCorner(u, u);
  }
  for (const Coupling& c : couplings) {
    const int ur = unknowns_of(c.row), uc = unknowns_of(c.col);
    k.block(offset[c.row], offset[c.col], ur, uc) += c.k.topLeftCorner(ur, uc);
    k.block(offset[c.col], offset[c.row], uc, ur) += c.k.topLeftCorner(ur, uc).transpose();
  }
  return k;
}

}  // namespace dda
