#include "solver/sparse_cholesky.hpp"

#include <dlfcn.h>
#include <malloc.h>
#include <omp.h>

#include <algorithm>
#include <cassert>
#include <iterator>
#include <limits>
#include <mutex>

namespace dda {
namespace {

// Each factorisation allocates the factor's entries afresh (a copy of the analysis, or a
// conversion for updates): megabytes, which glibc takes from the kernel by mmap and gives
// back on free, so every factorisation paid a page fault per 4 KiB while zeroing them; on
// the 1000-brick wall that was 22 % of a step (more than the factorisation's arithmetic).
// Serving large blocks from the heap and not trimming it keeps the pages mapped for the next
// factorisation. Process-wide, set once; the memory stays with the process.
void keep_large_allocations_mapped() {
  static const bool done = [] {
    mallopt(M_MMAP_THRESHOLD, 512 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024);
    return true;
  }();
  (void)done;
}

// CHOLMOD's supernodal factorisation and solve call BLAS, and whether two threads may call
// it at once depends on which BLAS the process loaded (Debian chooses it by alternatives).
// Debian's serial OpenBLAS (libopenblas0-serial) is not safe for concurrent callers: two
// strength-reduction trials factorising at once on two threads (dda fos) got corrupted
// factors, "not positive definite or not finite", where each alone ran clean. Its threaded
// build (libopenblas0-pthread, the one scripts/install-deps.sh installs) locks its shared
// buffers and, told to use one thread a call, runs each call on its caller's thread with the
// same kernels as the serial build: concurrent calls are safe. With the serial build (or a
// BLAS we cannot identify) the calls that reach BLAS take a process-wide lock. It cost the
// 1965-block slope's search, two trials at once, 135 s of waiting in 780 s of threads' time.
struct BlasPolicy {
  bool serialise = true;
};

const BlasPolicy& blas_policy() {
  static const BlasPolicy policy = [] {
    BlasPolicy p;
    // OpenBLAS's own entry points (openblas_get_parallel: 0 serial, 1 pthreads, 2 OpenMP).
    const auto get_parallel =
        reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
    const auto set_threads =
        reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    if (get_parallel != nullptr && set_threads != nullptr && get_parallel() == 1) {
      // One thread a call: the callers are the trials' threads, and the results are those of
      // the serial kernels whatever the cores.
      set_threads(1);
      p.serialise = false;
    }
    return p;
  }();
  return policy;
}

std::mutex& blas_mutex() {
  static std::mutex m;
  return m;
}

// Held around every call that reaches BLAS: the lock when the BLAS needs it, else nothing.
std::unique_lock<std::mutex> blas_lock() {
  if (blas_policy().serialise) return std::unique_lock<std::mutex>(blas_mutex());
  return {};
}

// A cholmod_sparse view of a compressed-column symmetric matrix stored as its lower triangle
// (no copy); the caller sets stype and sorted otherwise.
cholmod_sparse view_lower(int n, std::size_t nnz, const int* p, const int* i, const double* x) {
  cholmod_sparse a{};
  a.nrow = static_cast<size_t>(n);
  a.ncol = static_cast<size_t>(n);
  a.nzmax = nnz;
  a.p = const_cast<int*>(p);
  a.i = const_cast<int*>(i);
  a.x = const_cast<double*>(x);
  a.stype = -1;  // symmetric, lower triangle stored
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

}  // namespace

cholmod_sparse SparseCholesky::view_pattern() const {
  return view_lower(static_cast<int>(outer_.size()) - 1, inner_.size(), outer_.data(),
                    inner_.data(), values_.data());
}

bool blas_calls_serialised() { return blas_policy().serialise; }

SparseCholesky::SparseCholesky() {
  // Debian's CHOLMOD asks OpenMP for teams of 4 threads in some loops of the supernodal
  // factorisation. On a process pinned to one core (or two cores shared with other work)
  // the team's threads wait on each other: at 1000 bricks the settling wall spent ~12 % of
  // its time in libgomp. Dynamic adjustment lets the runtime give a team no more threads
  // than the cores it may use.
  omp_set_dynamic(1);
  keep_large_allocations_mapped();
  (void)blas_policy();  // before any call reaches BLAS

  cholmod_start(&common_);
  common_.supernodal = CHOLMOD_AUTO;  // simplicial LDL' when small, supernodal LL' when not
  common_.final_ll = 0;               // a simplicial factor stays LDL' (what updown needs)
  common_.print = 0;
}

SparseCholesky::~SparseCholesky() {
  if (solve_x_ != nullptr) cholmod_free_dense(&solve_x_, &common_);
  if (solve_y_ != nullptr) cholmod_free_dense(&solve_y_, &common_);
  if (solve_e_ != nullptr) cholmod_free_dense(&solve_e_, &common_);
  if (factor_ != nullptr) cholmod_free_factor(&factor_, &common_);
  if (symbolic_ != nullptr) cholmod_free_factor(&symbolic_, &common_);
  cholmod_finish(&common_);
}

bool SparseCholesky::same_pattern(const Eigen::SparseMatrix<double>& k) const {
  if (static_cast<int>(outer_.size()) != k.outerSize() + 1 ||
      static_cast<long>(inner_.size()) != k.nonZeros()) {
    return false;
  }
  return std::equal(outer_.begin(), outer_.end(), k.outerIndexPtr()) &&
         std::equal(inner_.begin(), inner_.end(), k.innerIndexPtr());
}

bool SparseCholesky::scatter_into_pattern(const Eigen::SparseMatrix<double>& k) {
  if (static_cast<int>(outer_.size()) != k.outerSize() + 1 ||
      static_cast<long>(inner_.size()) < k.nonZeros()) {
    return false;
  }
  values_.assign(inner_.size(), 0.0);
  const int* kp = k.outerIndexPtr();
  const int* ki = k.innerIndexPtr();
  const double* kx = k.valuePtr();
  for (Eigen::Index j = 0; j < k.outerSize(); ++j) {
    int at = outer_[static_cast<std::size_t>(j)];
    const int end = outer_[static_cast<std::size_t>(j) + 1];
    for (int q = kp[j]; q < kp[j + 1]; ++q) {  // both columns sorted: one merge
      while (at < end && inner_[static_cast<std::size_t>(at)] < ki[q]) ++at;
      if (at == end || inner_[static_cast<std::size_t>(at)] != ki[q]) return false;
      values_[static_cast<std::size_t>(at++)] = kx[q];
    }
  }
  return true;
}

void SparseCholesky::grow_pattern(const Eigen::SparseMatrix<double>& k) {
  const bool can_merge = static_cast<int>(outer_.size()) == k.outerSize() + 1;
  std::vector<int> outer(static_cast<std::size_t>(k.outerSize()) + 1, 0);
  std::vector<int> inner;
  inner.reserve(static_cast<std::size_t>(k.nonZeros()) + (can_merge ? inner_.size() / 8 : 0));
  const int* kp = k.outerIndexPtr();
  const int* ki = k.innerIndexPtr();
  for (Eigen::Index j = 0; j < k.outerSize(); ++j) {
    if (can_merge) {
      std::set_union(ki + kp[j], ki + kp[j + 1], inner_.begin() + outer_[static_cast<std::size_t>(j)],
                     inner_.begin() + outer_[static_cast<std::size_t>(j) + 1], std::back_inserter(inner));
    } else {
      inner.insert(inner.end(), ki + kp[j], ki + kp[j + 1]);
    }
    outer[static_cast<std::size_t>(j) + 1] = static_cast<int>(inner.size());
  }
  // Entries the present matrix does not have are kept while they are few: a contact that
  // opened beyond the search distance for some steps and comes back finds its place. Past
  // kPatternSlack of the matrix's own entries, the pattern starts again from the matrix's.
  if (static_cast<double>(inner.size()) > (1.0 + kPatternSlack) * static_cast<double>(k.nonZeros())) {
    outer.assign(kp, kp + k.outerSize() + 1);
    inner.assign(ki, ki + k.nonZeros());
  }
  outer_ = std::move(outer);
  inner_ = std::move(inner);
}

// A positive definite matrix has an LL' without a failed column (CHOLMOD stops there and
// sets minor) and an LDL' with D > 0 (CHOLMOD's LDL' does not stop at a negative pivot, so
// the check is made here: D(j) is the first entry of column j of a simplicial factor).
bool SparseCholesky::positive_pivots() const {
  if (factor_->minor < factor_->n) return false;
  if (factor_->is_ll) return true;
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
  const bool was_factored = factored_;
  factored_ = false;
  // The matrix's values in the analysed pattern (values_): its own when its pattern is the
  // analysed one; else scattered into the analysed pattern when that holds all of its
  // entries (a contact gone since the analysis leaves explicit zeros); else a new analysis,
  // of the union of the two patterns (grow_pattern).
  bool own_pattern = symbolic_ != nullptr && same_pattern(lower);
  const bool analysed = own_pattern || (symbolic_ != nullptr && scatter_into_pattern(lower));
  if (!analysed) {
    if (factor_ != nullptr) cholmod_free_factor(&factor_, &common_);
    if (symbolic_ != nullptr) cholmod_free_factor(&symbolic_, &common_);
    grow_pattern(lower);
    own_pattern = same_pattern(lower);
    if (!own_pattern) scatter_into_pattern(lower);  // the union holds it: cannot fail
  }
  // record() keeps the matrix factorised, and the factorisation below reads it from here.
  if (own_pattern) values_.assign(lower.valuePtr(), lower.valuePtr() + lower.nonZeros());
  modifications_.clear();
  if (!analysed) {
    cholmod_sparse a = view_pattern();
    if (!analyse(a)) return false;
  }
  // A factor that was refactorised in place keeps its form; one that was converted for
  // updates (or failed) starts again from the analysis.
  const bool reusable =
      was_factored && factor_ != nullptr && factor_->is_super == symbolic_->is_super && !modified_;
  if (!reusable) {
    if (factor_ != nullptr) cholmod_free_factor(&factor_, &common_);
    factor_ = cholmod_copy_factor(symbolic_, &common_);
    if (factor_ == nullptr) return false;
  }
  modified_ = false;
  // The matrix in the factor's order (make_permuted_layout), handed over as already
  // permuted: CHOLMOD reads the factor's ordering only to decide whether to permute its
  // input, and the solves and updates still use the factor's permutation.
  for (std::size_t q = 0; q < permuted_position_.size(); ++q) {
    permuted_values_[static_cast<std::size_t>(permuted_position_[q])] = values_[q];
  }
  cholmod_sparse permuted = view_lower(static_cast<int>(permuted_outer_.size()) - 1,
                                       permuted_inner_.size(), permuted_outer_.data(),
                                       permuted_inner_.data(), permuted_values_.data());
  permuted.stype = factor_->is_super ? -1 : 1;
  permuted.sorted = permuted_sorted_ ? 1 : 0;
  const int ordering = factor_->ordering;
  factor_->ordering = CHOLMOD_NATURAL;
  bool ok = false;
  {
    const std::unique_lock<std::mutex> lock = blas_lock();
    ok = cholmod_factorize(&permuted, factor_, &common_) != 0;
  }
  factor_->ordering = ordering;
  if (!ok) return false;
  factored_ = common_.status == CHOLMOD_OK && positive_pivots();
  if (factored_ && !tables_made_) {
    make_cost_tables();
    tables_made_ = true;
  }
  return factored_;
}

void SparseCholesky::make_permuted_layout() {
  const int n = static_cast<int>(outer_.size()) - 1;
  const auto* perm = static_cast<const int*>(symbolic_->Perm);
  permuted_outer_.assign(static_cast<std::size_t>(n) + 1, 0);
  permuted_inner_.resize(inner_.size());
  permuted_position_.resize(inner_.size());
  permuted_values_.assign(inner_.size(), 0.0);
  // Entries in the order CHOLMOD's own permutation leaves them in (rowfac's sums run in the
  // order of a column's entries, so this keeps every factor as it was, bit for bit): for a
  // simplicial factor, the upper triangle filled column by column of P K P', each new
  // column's entries in the analysed pattern's order (cholmod_transpose_sym, marked
  // unsorted); for a supernodal one, that transposed again, which sorts it.
  const auto place = [&](auto&& visit) {
    for (int j = 0; j < n; ++j) {
      const int old = perm[j];
      for (int q = outer_[static_cast<std::size_t>(old)]; q < outer_[static_cast<std::size_t>(old) + 1]; ++q) {
        const int i = inverse_perm_[static_cast<std::size_t>(inner_[static_cast<std::size_t>(q)])];
        visit(j, i, q);
      }
    }
  };
  if (!symbolic_->is_super) {
    place([&](int j, int i, int) { ++permuted_outer_[static_cast<std::size_t>(std::max(i, j)) + 1]; });
    for (int j = 0; j < n; ++j) {
      permuted_outer_[static_cast<std::size_t>(j) + 1] += permuted_outer_[static_cast<std::size_t>(j)];
    }
    std::vector<int> next(permuted_outer_.begin(), permuted_outer_.end() - 1);
    place([&](int j, int i, int q) {
      const int at = next[static_cast<std::size_t>(std::max(i, j))]++;
      permuted_inner_[static_cast<std::size_t>(at)] = std::min(i, j);
      permuted_position_[static_cast<std::size_t>(q)] = at;
    });
    permuted_sorted_ = false;
    return;
  }
  struct Entry {
    int column, row, from;
  };
  std::vector<Entry> entries;
  entries.reserve(inner_.size());
  place([&](int j, int i, int q) { entries.push_back({std::min(i, j), std::max(i, j), q}); });
  std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
    return x.column != y.column ? x.column < y.column : x.row < y.row;
  });
  for (std::size_t k = 0; k < entries.size(); ++k) {
    ++permuted_outer_[static_cast<std::size_t>(entries[k].column) + 1];
    permuted_inner_[k] = entries[k].row;
    permuted_position_[static_cast<std::size_t>(entries[k].from)] = static_cast<int>(k);
  }
  for (int j = 0; j < n; ++j) {
    permuted_outer_[static_cast<std::size_t>(j) + 1] += permuted_outer_[static_cast<std::size_t>(j)];
  }
  permuted_sorted_ = true;
}

bool SparseCholesky::analyse(cholmod_sparse& a) {
  if (a.nrow >= static_cast<size_t>(kNestedDissectionRows)) {
    common_.nmethods = 2;  // AMD and METIS, the smaller factor kept
    common_.method[0].ordering = CHOLMOD_AMD;
    common_.method[1].ordering = CHOLMOD_METIS;
  } else {
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_AMD;
  }
  symbolic_ = cholmod_analyze(&a, &common_);
  if (symbolic_ == nullptr) return false;
  ++analyses_;
  const auto* perm = static_cast<const int*>(symbolic_->Perm);
  inverse_perm_.assign(symbolic_->n, 0);
  for (size_t i = 0; i < symbolic_->n; ++i) inverse_perm_[perm[i]] = static_cast<int>(i);
  make_permuted_layout();
  tables_made_ = false;
  return true;
}

FactorRecord SparseCholesky::record() const {
  FactorRecord r;
  r.analysed = symbolic_ != nullptr;
  r.outer = outer_;
  r.inner = inner_;
  r.values = values_;
  r.factored = has_factor();
  r.analyses = analyses_;
  r.modifications = modifications_;
  return r;
}

bool SparseCholesky::restore(const FactorRecord& record) {
  if (factor_ != nullptr) cholmod_free_factor(&factor_, &common_);
  if (symbolic_ != nullptr) cholmod_free_factor(&symbolic_, &common_);
  factored_ = false;
  modified_ = false;
  modifications_.clear();
  outer_.clear();
  inner_.clear();
  values_.clear();
  analyses_ = record.analyses;
  if (!record.analysed) return true;
  const int n = static_cast<int>(record.outer.size()) - 1;
  if (n < 0 || static_cast<std::size_t>(record.outer.back()) != record.inner.size() ||
      record.values.size() != record.inner.size()) {
    return false;
  }
  // factorize() on the emptied object: the stored pattern becomes the analysed one, analysed
  // and factorised as when it was made.
  Eigen::SparseMatrix<double> lower = Eigen::Map<const Eigen::SparseMatrix<double>>(
      n, n, static_cast<Eigen::Index>(record.inner.size()), record.outer.data(), record.inner.data(),
      record.values.data());
  lower.makeCompressed();
  const bool factorised = factorize(lower);
  analyses_ = record.analyses;
  if (!record.factored) {
    factored_ = false;  // the recorded object held no factor (its factorisation failed)
    return symbolic_ != nullptr;
  }
  if (!factorised) return false;
  for (const FactorModification& m : record.modifications) {
    if (!modify(m.terms, m.update)) return false;
  }
  return true;
}

bool SparseCholesky::modify(const std::vector<RankOneTerm>& terms, bool update) {
  assert(has_factor());
  if (terms.empty()) return true;
  modifications_.push_back({update, terms});
  if (!modified_) {
    // updown needs a simplicial LDL': convert a supernodal LL' (a copy of its entries) or
    // take the simplicial one as it is.
    if (factor_->is_super || factor_->is_ll) {
      if (!cholmod_change_factor(CHOLMOD_REAL, 0, 0, 1, 1, factor_, &common_)) {
        factored_ = false;
        return false;
      }
    }
    modified_ = true;
  }
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
  const double simplicial = kSimplicialFlopNs * column_count_squares_;
  return symbolic_->is_super ? std::min(simplicial, kSupernodalEntryNs * factor_entries_)
                              : simplicial;
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
  return kUpdateEntryNs * cost;
}

double SparseCholesky::solve_cost() const {
  const double per_entry = 0.4 + 0.6 * std::min(1.0, factor_entries_ / 5e6);
  return 2.0 * factor_entries_ * per_entry;
}

// Column counts and elimination-tree parents of the factor just made, from its own
// structure: a simplicial factor stores each column's rows (the parent is the first row below
// the diagonal); a supernodal one stores each supernode's rows once, its columns j, j+1, ...
// are a chain, and the last one's parent is the first row below the supernode.
void SparseCholesky::make_cost_tables() {
  const int n = static_cast<int>(factor_->n);
  std::vector<int> count(static_cast<std::size_t>(n), 0);
  std::vector<int> parent(static_cast<std::size_t>(n), n);  // n: a root
  if (factor_->is_super) {
    const auto* super = static_cast<const int*>(factor_->super);
    const auto* pi = static_cast<const int*>(factor_->pi);
    const auto* rows = static_cast<const int*>(factor_->s);
    for (size_t s = 0; s < factor_->nsuper; ++s) {
      const int k1 = super[s], k2 = super[s + 1];
      const int nrows = pi[s + 1] - pi[s];
      const int ncols = k2 - k1;
      int below = n;
      for (int k = pi[s] + ncols; k < pi[s + 1]; ++k) below = std::min(below, rows[k]);
      for (int j = k1; j < k2; ++j) {
        count[static_cast<std::size_t>(j)] = nrows - (j - k1);
        parent[static_cast<std::size_t>(j)] = j + 1 < k2 ? j + 1 : below;
      }
    }
  } else {
    const auto* p = static_cast<const int*>(factor_->p);
    const auto* i = static_cast<const int*>(factor_->i);
    const auto* nz = static_cast<const int*>(factor_->nz);
    for (int j = 0; j < n; ++j) {
      count[static_cast<std::size_t>(j)] = nz[j];
      for (int k = p[j] + 1; k < p[j] + nz[j]; ++k) {
        parent[static_cast<std::size_t>(j)] = std::min(parent[static_cast<std::size_t>(j)], i[k]);
      }
    }
  }
  path_cost_.assign(static_cast<std::size_t>(n), 0.0);
  column_count_squares_ = 0.0;
  factor_entries_ = 0.0;
  // A parent's index is larger than its child's: fill the table from the root down.
  for (int j = n - 1; j >= 0; --j) {
    const auto u = static_cast<std::size_t>(j);
    const int up = parent[u];
    path_cost_[u] = count[u] + (up < n ? path_cost_[static_cast<std::size_t>(up)] : 0.0);
    column_count_squares_ += static_cast<double>(count[u]) * count[u];
    factor_entries_ += count[u];
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
  {
    const std::unique_lock<std::mutex> lock = blas_lock();
    if (cholmod_solve2(CHOLMOD_A, factor_, &rhs, nullptr, &solve_x_, nullptr, &solve_y_,
                       &solve_e_, &common_) == 0 ||
        solve_x_ == nullptr) {
      // (Out of memory: an answer the callers reject, as they reject any non-finite one.)
      return Eigen::VectorXd::Constant(b.size(), std::numeric_limits<double>::quiet_NaN());
    }
  }
  return Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(solve_x_->x), b.size());
}

}  // namespace dda
