#include "solver/linear_solver.hpp"

#include <algorithm>

namespace dda {

std::optional<Eigen::VectorXd> solve_dense(const BlockSystem& system) {
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(system.dense());
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return std::nullopt;
  return Eigen::VectorXd(ldlt.solve(system.rhs));
}

// ---- rigid blocks: x and y in the dof map's reduced layout; each block
// acts by its leading unknowns_of(row) x unknowns_of(col) corner (BlockSystem) ----
namespace {

// y[0, Out) += B x[0, In) for one 6 x 6 block A of the block system (or its rigid 3-unknown
// corner): B = A's leading Out x In corner, or with kTransposed A's leading In x Out corner
// transposed. At fixed sizes the compiler unrolls it (the dynamic-size product of the corner
// was a tenth of a moving scene's time).
template <int Out, int In, bool kTransposed>
void block_product(const Mat6& a, const double* x, double* y) {
  for (int i = 0; i < Out; ++i) {
    double sum = 0.0;
    for (int j = 0; j < In; ++j) sum += (kTransposed ? a(j, i) : a(i, j)) * x[j];
    y[i] += sum;
  }
}

// The same for A's leading rows x cols corner (each 6 or kRigidUnknowns), or its transpose.
template <bool kTransposed>
void corner_product(const Mat6& a, int rows, int cols, const double* x, double* y) {
  constexpr int kR = BlockSystem::kRigidUnknowns;
  const int out = kTransposed ? cols : rows, in = kTransposed ? rows : cols;
  if (out == 6 && in == 6) {
    block_product<6, 6, kTransposed>(a, x, y);
  } else if (out == 6) {
    block_product<6, kR, kTransposed>(a, x, y);
  } else if (in == 6) {
    block_product<kR, 6, kTransposed>(a, x, y);
  } else {
    block_product<kR, kR, kTransposed>(a, x, y);
  }
}

}  // namespace

Eigen::VectorXd multiply(const BlockSystem& system, const Eigen::VectorXd& x) {
  const std::vector<int>& o = system.offset;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(x.size());
  const double* xs = x.data();
  double* ys = y.data();
  for (int b = 0; b < system.block_rows(); ++b) {
    const int u = system.unknowns_of(b);
    corner_product<false>(system.diagonal[b], u, u, xs + o[b], ys + o[b]);
  }
  for (const BlockSystem::Coupling& c : system.couplings) {
    const int ur = system.unknowns_of(c.row), uc = system.unknowns_of(c.col);
    corner_product<false>(c.k, ur, uc, xs + o[c.col], ys + o[c.row]);
    corner_product<true>(c.k, ur, uc, xs + o[c.row], ys + o[c.col]);
  }
  return y;
}
// ---- end rigid blocks ----

std::optional<Eigen::VectorXd> CholmodSolver::solve(const BlockSystem& system) {
  Eigen::SparseMatrix<double> k = system.lower_triangle();
  k.makeCompressed();
  ++stats_.factorisations;
  last_path_ = Path::Factorised;
  factored_rows_ = -1;
  refresh_ = false;
  const bool factored = factor_.factorize(k);
  stats_.analyses = factor_.analyses();
  if (!factored) return std::nullopt;
  factored_rows_ = system.block_rows();
  since_factor_cost_ = factor_.refactorisation_cost() + factor_.solve_cost();
  since_factor_solves_ = 1;
  return factor_.solve(system.rhs);
}

CholmodSolver::Record CholmodSolver::record() const {
  return Record{factor_.record(), factored_rows_,      refresh_,   since_factor_cost_,
                since_factor_solves_, last_path_, stats_};
}

bool CholmodSolver::restore(const Record& record) {
  factored_rows_ = record.factored_rows;
  refresh_ = record.refresh;
  since_factor_cost_ = record.since_factor_cost;
  since_factor_solves_ = record.since_factor_solves;
  last_path_ = record.last_path;
  stats_ = record.stats;
  if (factor_.restore(record.factor)) return true;
  factored_rows_ = -1;  // no factor: the next solve factorises
  return false;
}

std::optional<Eigen::VectorXd> CholmodSolver::solve_reusing(const BlockSystem& system) {
  if (!reuse_ || refresh_ || !factor_.has_factor() || system.block_rows() != factored_rows_) {
    return solve(system);
  }
  return answer_by_cg(system, Path::Reused);
}

std::optional<Eigen::VectorXd> CholmodSolver::answer_by_cg(const BlockSystem& system, Path path) {
  std::optional<Eigen::VectorXd> x = conjugate_gradients(system);
  if (!x) return solve(system);
  last_path_ = path;
  if (check_) compare_with_plain(system, *x);
  return x;
}

std::optional<Eigen::VectorXd> CholmodSolver::solve_modified(const BlockSystem& system,
                                                             const std::vector<RankOneTerm>& added,
                                                             const std::vector<RankOneTerm>& removed) {
  if (!reuse_ || refresh_ || !factor_.has_factor() || system.block_rows() != factored_rows_) {
    return solve(system);
  }
  if (added.empty() && removed.empty()) return solve_reusing(system);
  // Three ways to the answer, by the modelled cost (multiply-adds; deterministic, so a run's
  // path does not depend on the machine): factorise; update the factor by the springs and
  // run CG for the drift; or run CG on the factor as it is, about one more iteration per
  // changed spring.
  const double iteration = cg_iteration_cost(system);
  const double factorise = factor_.refactorisation_cost();
  const double modification = factor_.modification_cost(added) + factor_.modification_cost(removed);
  const double update = modification + kExpectedCgIterations * iteration;
  const double cg_only =
      (static_cast<double>(added.size() + removed.size()) + kExpectedCgIterations) * iteration;
  if (std::min(update, cg_only) > factorise) return solve(system);
  if (cg_only <= update) return answer_by_cg(system, Path::Reused);
  ++stats_.modifications;
  since_factor_cost_ += modification;
  // Updates first: the matrix stays positive definite all along.
  if (!factor_.modify(added, true) || !factor_.modify(removed, false)) return solve(system);
  // The updated factor is the factor of the previous solve's matrix plus the changed springs:
  // exact when that matrix was factorised in this iteration's step, close to K when it was
  // an earlier step's (CG makes up the difference).
  return answer_by_cg(system, Path::Modified);
}

double CholmodSolver::cg_iteration_cost(const BlockSystem& system) const {
  // A solve with the factor and a product with K (36 multiply-adds for a diagonal block, 72
  // for a coupling used both ways).
  const double product = 36.0 * system.block_rows() + 72.0 * static_cast<double>(system.couplings.size());
  return factor_.solve_cost() + kProductNs * product;
}

int CholmodSolver::cg_cap(const BlockSystem& system) const {
  const double affordable =
      kCgShareOfRefactor * factor_.refactorisation_cost() / cg_iteration_cost(system);
  return static_cast<int>(std::clamp(affordable, static_cast<double>(kCgMinIterations),
                                     static_cast<double>(kCgMaxIterations)));
}

std::optional<Eigen::VectorXd> CholmodSolver::conjugate_gradients(const BlockSystem& system) {
  const Eigen::VectorXd& b = system.rhs;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd r = b;
  Eigen::VectorXd z = factor_.solve(r);
  const double start = r.dot(z);
  ++stats_.reused;
  if (!(start > 0.0)) {
    // b = 0 (nothing moves), or F is not positive definite on b: no CG.
    if (b.isZero(0.0)) return x;
    ++stats_.cg_failures;
    return std::nullopt;
  }
  const int cap = cg_cap(system);
  Eigen::VectorXd p = z;
  double rz = start;
  for (int k = 1; k <= cap; ++k) {
    ++stats_.cg_iterations;
    const Eigen::VectorXd q = multiply(system, p);
    const double curvature = p.dot(q);
    if (!(curvature > 0.0)) break;  // K is not positive definite along p: factorise
    const double alpha = rz / curvature;
    x.noalias() += alpha * p;
    r.noalias() -= alpha * q;
    z = factor_.solve(r);
    const double rz_next = r.dot(z);
    if (rz_next <= kCgTolerance * kCgTolerance * start) {
      // Converged. The refresh (linear_solver.hpp): this solve's CG against the average
      // cost of a solve since the factorisation.
      const double cost = (k + 1) * cg_iteration_cost(system);  // + the first solve with F
      since_factor_cost_ += cost;
      ++since_factor_solves_;
      if (cost * since_factor_solves_ > since_factor_cost_) refresh_ = true;
      return x;
    }
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  ++stats_.cg_failures;
  return std::nullopt;
}

std::optional<Eigen::VectorXd> CholmodSolver::solve_low_rank_coupled(
    const BlockSystem& system, const Eigen::VectorXd& b_in, const std::vector<RankOneTerm>& u,
    const std::vector<RankOneTerm>& v, double tolerance, const Eigen::VectorXd* start) {
  const auto dot = [](const RankOneTerm& t, const Eigen::VectorXd& x) {
    double sum = 0.0;
    for (const auto& [i, value] : t.entries) sum += value * x[i];
    return sum;
  };
  const auto apply = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd y = multiply(system, x);
    for (std::size_t j = 0; j < u.size(); ++j) {
      const double s = dot(v[j], x);
      if (s != 0.0) {
        for (const auto& [i, value] : u[j].entries) y[i] += value * s;
      }
    }
    return y;
  };
  // With a start, the change from it: A (start + x) = b_in.
  const Eigen::VectorXd b = start ? Eigen::VectorXd(b_in - apply(*start)) : b_in;
  const double b_norm = b.norm();
  const double goal = tolerance * b_in.norm();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  if (b_norm <= goal) return start ? Eigen::VectorXd(*start) : x;
  const int cap = std::min<int>(kGmresMaxIterations, static_cast<int>(b.size()));
  // Arnoldi with modified Gram-Schmidt on A F^-1; Givens rotations keep the least-squares
  // problem triangular.
  std::vector<Eigen::VectorXd> basis;
  basis.reserve(static_cast<std::size_t>(cap) + 1);
  if (hessenberg_.rows() < cap + 1 || hessenberg_.cols() < cap) hessenberg_.resize(cap + 1, cap);
  Eigen::MatrixXd& h = hessenberg_;
  Eigen::VectorXd cs = Eigen::VectorXd::Zero(cap), sn = Eigen::VectorXd::Zero(cap);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(cap + 1);
  g[0] = b_norm;
  basis.push_back(b / b_norm);
  int k = 0;
  for (; k < cap; ++k) {
    ++stats_.cg_iterations;
    h.col(k).head(k + 2).setZero();  // the entries this column uses
    Eigen::VectorXd w = apply(factor_.solve(basis[static_cast<std::size_t>(k)]));
    for (int i = 0; i <= k; ++i) {
      h(i, k) = w.dot(basis[static_cast<std::size_t>(i)]);
      w -= h(i, k) * basis[static_cast<std::size_t>(i)];
    }
    const double w_norm = w.norm();
    h(k + 1, k) = w_norm;
    for (int i = 0; i < k; ++i) {
      const double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
      h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
      h(i, k) = t;
    }
    const double r = std::hypot(h(k, k), h(k + 1, k));
    if (!(r > 0.0)) return std::nullopt;
    cs[k] = h(k, k) / r;
    sn[k] = h(k + 1, k) / r;
    h(k, k) = r;
    h(k + 1, k) = 0.0;
    g[k + 1] = -sn[k] * g[k];
    g[k] = cs[k] * g[k];
    // (w_norm 0: the Krylov space holds the answer, and g[k + 1] is 0.)
    if (std::abs(g[k + 1]) <= goal || w_norm == 0.0 || k + 1 == cap) {
      ++k;
      break;
    }
    basis.push_back(w / w_norm);
  }
  if (std::abs(g[k]) > goal) return std::nullopt;
  const Eigen::VectorXd y =
      h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  Eigen::VectorXd z = Eigen::VectorXd::Zero(b.size());
  for (int i = 0; i < k; ++i) z += y[i] * basis[static_cast<std::size_t>(i)];
  x = factor_.solve(z);
  if (!x.allFinite()) return std::nullopt;
  if (start) x += *start;
  return x;
}

void CholmodSolver::compare_with_plain(const BlockSystem& system, const Eigen::VectorXd& x) {
  Eigen::SparseMatrix<double> k = system.lower_triangle();
  k.makeCompressed();
  SparseCholesky plain;
  if (!plain.factorize(k)) return;
  const Eigen::VectorXd reference = plain.solve(system.rhs);
  const double scale = reference.norm();
  if (scale > 0.0) {
    stats_.largest_difference_from_plain =
        std::max(stats_.largest_difference_from_plain, (x - reference).norm() / scale);
  }
}

}  // namespace dda
