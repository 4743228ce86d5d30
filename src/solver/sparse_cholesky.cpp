#include "solver/sparse_cholesky.hpp"

#include <algorithm>
#include <cassert>

namespace dda {
namespace {

// A cholmod_sparse view of an Eigen compressed lower triangle (no copy).
cholmod_sparse view_lower(const Eigen::SparseMatrix<double>& k) {
  cholmod_sparse a{};
  a.nrow = static_cast<size_t>(k.rows());
  a.ncol = static_cast<size_t>(k.cols());
  a.nzmax = static_cast<size_t>(k.nonZeros());
  a.p = const_cast<int*>(k.outerIndexPtr());
  a.i = const_cast<int*>(k.innerIndexPtr());
  a.x = const_cast<double*>(k.valuePtr());
  a.stype = -1;  // symmetric, lower triangle stored
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

}  // namespace

SparseCholesky::SparseCholesky() {
  cholmod_start(&common_);
  common_.supernodal = CHOLMOD_SIMPLICIAL;  // updown works on simplicial LDL'
  common_.final_ll = 0;
  common_.print = 0;
}

SparseCholesky::~SparseCholesky() {
  if (factor_ != nullptr) cholmod_free_factor(&factor_, &common_);
  cholmod_finish(&common_);
}

bool SparseCholesky::same_pattern(const Eigen::SparseMatrix<double>& k) const {
  if (factor_ == nullptr || static_cast<int>(outer_.size()) != k.outerSize() + 1 ||
      static_cast<long>(inner_.size()) != k.nonZeros()) {
    return false;
  }
  return std::equal(outer_.begin(), outer_.end(), k.outerIndexPtr()) &&
         std::equal(inner_.begin(), inner_.end(), k.innerIndexPtr());
}

// LDL' of a positive definite matrix has D > 0. (CHOLMOD's LDL' does not stop at a negative
// pivot, so the check is made here.) D(j) is the first entry of column j of the factor.
bool SparseCholesky::positive_pivots() const {
  if (factor_->minor < factor_->n) return false;
  const auto* p = static_cast<const int*>(factor_->p);
  const auto* x = static_cast<const double*>(factor_->x);
  for (size_t j = 0; j < factor_->n; ++j) {
    const double d = x[p[j]];
    if (!(d > 0.0)) return false;
  }
  return true;
}

bool SparseCholesky::factorize(const Eigen::SparseMatrix<double>& lower) {
  assert(lower.isCompressed());
  cholmod_sparse a = view_lower(lower);
  factored_ = false;
  if (!same_pattern(lower)) {
    if (factor_ != nullptr) cholmod_free_factor(&factor_, &common_);
    factor_ = cholmod_analyze(&a, &common_);
    if (factor_ == nullptr) return false;
    outer_.assign(lower.outerIndexPtr(), lower.outerIndexPtr() + lower.outerSize() + 1);
    inner_.assign(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros());
    const auto* perm = static_cast<const int*>(factor_->Perm);
    inverse_perm_.assign(factor_->n, 0);
    for (size_t i = 0; i < factor_->n; ++i) inverse_perm_[perm[i]] = static_cast<int>(i);
  } else if (!factor_->is_ll && factor_->xtype != CHOLMOD_PATTERN) {
    // Refactorising a modified factor: start from its symbolic form again.
    cholmod_change_factor(CHOLMOD_PATTERN, 0, 0, 0, 1, factor_, &common_);
  }
  if (!cholmod_factorize(&a, factor_, &common_)) return false;
  factored_ = common_.status == CHOLMOD_OK && positive_pivots();
  if (factored_) make_cost_tables();
  return factored_;
}

bool SparseCholesky::modify(const std::vector<RankOneTerm>& terms, bool update) {
  assert(has_factor());
  if (terms.empty()) return true;
  std::size_t nnz = 0;
  for (const RankOneTerm& t : terms) nnz += t.entries.size();
  cholmod_sparse* c = cholmod_allocate_sparse(factor_->n, terms.size(), nnz, 1, 1, 0,
                                              CHOLMOD_REAL, &common_);
  if (c == nullptr) return false;
  auto* cp = static_cast<int*>(c->p);
  auto* ci = static_cast<int*>(c->i);
  auto* cx = static_cast<double*>(c->x);
  int k = 0;
  std::vector<std::pair<int, double>> column;
  for (std::size_t j = 0; j < terms.size(); ++j) {
    cp[j] = k;
    // Rows in the factor's permuted order, sorted, as cholmod_updown requires.
    column.clear();
    for (const auto& [row, value] : terms[j].entries) column.emplace_back(inverse_perm_[row], value);
    std::sort(column.begin(), column.end());
    for (const auto& [row, value] : column) {
      ci[k] = row;
      cx[k] = value;
      ++k;
    }
  }
  cp[terms.size()] = k;
  const int ok = cholmod_updown(update ? 1 : 0, c, factor_, &common_);
  cholmod_free_sparse(&c, &common_);
  factored_ = ok && common_.status == CHOLMOD_OK && positive_pivots();
  return factored_;
}

double SparseCholesky::refactorisation_cost() const {
  assert(has_factor());
  return refactorisation_cost_;
}

double SparseCholesky::modification_cost(const std::vector<RankOneTerm>& terms) const {
  assert(has_factor());
  const int n = static_cast<int>(path_cost_.size());
  double cost = 0.0;
  for (const RankOneTerm& t : terms) {
    int first = n;
    for (const auto& entry : t.entries) first = std::min(first, inverse_perm_[entry.first]);
    if (first < n) cost += path_cost_[static_cast<std::size_t>(first)];
  }
  return cost;
}

void SparseCholesky::make_cost_tables() {
  const auto* p = static_cast<const int*>(factor_->p);
  const auto* i = static_cast<const int*>(factor_->i);
  const auto* nz = static_cast<const int*>(factor_->nz);
  const int n = static_cast<int>(factor_->n);
  path_cost_.assign(static_cast<std::size_t>(n), 0.0);
  refactorisation_cost_ = 0.0;
  // A parent's index is larger than its child's: fill the table from the root down.
  for (int j = n - 1; j >= 0; --j) {
    int parent = n;  // the first row below the diagonal in column j
    for (int k = p[j] + 1; k < p[j] + nz[j]; ++k) parent = std::min(parent, i[k]);
    path_cost_[static_cast<std::size_t>(j)] =
        nz[j] + (parent < n ? path_cost_[static_cast<std::size_t>(parent)] : 0.0);
    refactorisation_cost_ += static_cast<double>(nz[j]) * nz[j];
  }
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) {
  assert(has_factor());
  cholmod_dense rhs{};
  rhs.nrow = static_cast<size_t>(b.size());
  rhs.ncol = 1;
  rhs.nzmax = rhs.nrow;
  rhs.d = rhs.nrow;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor_, &rhs, &common_);
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(x->x), b.size());
  cholmod_free_dense(&x, &common_);
  return out;
}

}  // namespace dda
