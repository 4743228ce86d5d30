// A CHOLMOD factorisation that can be modified in place by low-rank updates and downdates
// (Davis and Hager, cholmod_updown): inside the open-close loop only the springs of the
// contacts that changed mode differ from one iteration to the next, so the factor of the
// step's first iteration is updated instead of refactorised.
//
// CHOLMOD chooses by the analysis (CHOLMOD_AUTO: flops per factor entry >= 40) between a
// simplicial LDL' (small systems) and a supernodal LL' (dense BLAS kernels, from Debian's
// OpenBLAS when installed: 14 ms instead of 26 ms for the 1000-brick wall on one core).
// Updates work on a simplicial LDL' only, so modify() converts a supernodal factor first
// (cholmod_change_factor, a copy of the entries) and the next factorize() starts again from
// a kept copy of the supernodal analysis.
#pragma once

#include <cholmod.h>

#include <Eigen/Sparse>
#include <optional>
#include <vector>

namespace dda {

// A symmetric rank-one term sign * c c^T, c sparse: (row, value) pairs.
struct RankOneTerm {
  std::vector<std::pair<int, double>> entries;
};

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Factorises the symmetric matrix given by its lower triangle (analysis kept while the
  // pattern is unchanged). False when it is not positive definite. Orderings: AMD, and for
  // large systems (at least kNestedDissectionRows rows) METIS nested dissection as well,
  // the one with the smaller factor kept.
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  // On the 1000-brick wall (6000 rows) AMD's factor is the smaller (6.9e7 flops against
  // METIS's 8.9e7) and its analysis 3 ms against 9 ms; at 10000 bricks (60000 rows) a
  // factorisation with METIS takes 0.27-0.32 s supernodal on one core (issue 10's
  // measurement), so both are tried there and CHOLMOD keeps the one with fewer entries.
  static constexpr int kNestedDissectionRows = 20000;

  // K += c c^T for every term (update = true) or K -= c c^T (update = false). False when the
  // result is not positive definite (the factor is then unusable until factorize()).
  bool modify(const std::vector<RankOneTerm>& terms, bool update);

  // A cost model of the two ways to the factor of a modified matrix, in "entry operations"
  // (deterministic, from the structure of the last factorisation, so a run's path does not
  // depend on the machine's timing; both read tables made once per factorisation):
  //  - refactorisation_cost(): sum over columns j of L of nnz(L(:,j))^2, the flop count of
  //    a left-looking LDL';
  //  - modification_cost(terms): for each rank-one term, the sum of nnz(L(:,j)) over the
  //    columns j that cholmod_updown visits, the elimination-tree path from the term's first
  //    row (in the factor's order) to the root. (Updates add fill, so later ones cost a
  //    little more than the model says.)
  double refactorisation_cost() const;
  double modification_cost(const std::vector<RankOneTerm>& terms) const;

  // Solves with the present factor. Requires a successful factorize().
  Eigen::VectorXd solve(const Eigen::VectorXd& b);

  bool has_factor() const { return factor_ != nullptr && factored_; }
  bool supernodal() const { return factor_ != nullptr && factor_->is_super; }
  // Multiply-adds of one solve with the factor (two triangular sweeps over nnz(L)).
  double solve_cost() const { return 2.0 * factor_entries_; }

 private:
  bool same_pattern(const Eigen::SparseMatrix<double>& k) const;
  bool positive_pivots() const;
  void make_cost_tables();

  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  cholmod_factor* symbolic_ = nullptr;  // the analysis of the present pattern, kept
  std::vector<int> outer_;
  std::vector<int> inner_;
  std::vector<int> inverse_perm_;  // row i of A is row inverse_perm_[i] of P A
  // The cost model's tables, made by factorize(): for each column j of L (factor's order),
  // the summed column counts from j up the elimination tree to the root; and sum nnz^2.
  std::vector<double> path_cost_;
  double refactorisation_cost_ = 0.0;
  double factor_entries_ = 0.0;  // nnz(L) of the last factorisation
  bool factored_ = false;
  bool modified_ = false;  // converted to simplicial LDL' and updated since factorised
};

}  // namespace dda
