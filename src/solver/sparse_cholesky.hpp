// A CHOLMOD LDL' factorisation that can be modified in place by low-rank updates and
// downdates (Davis and Hager, cholmod_updown): inside the open-close loop only the springs of
// the contacts that changed mode differ from one iteration to the next, so the factor of the
// step's first iteration is updated instead of refactorised.
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
  // pattern is unchanged). False when it is not positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& lower);

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

 private:
  bool same_pattern(const Eigen::SparseMatrix<double>& k) const;
  bool positive_pivots() const;
  void make_cost_tables();

  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  std::vector<int> outer_;
  std::vector<int> inner_;
  std::vector<int> inverse_perm_;  // row i of A is row inverse_perm_[i] of P A
  // The cost model's tables, made by factorize(): for each column j of L (factor's order),
  // the summed column counts from j up the elimination tree to the root; and sum nnz^2.
  std::vector<double> path_cost_;
  double refactorisation_cost_ = 0.0;
  bool factored_ = false;
};

}  // namespace dda
