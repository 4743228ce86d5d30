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

// Whether factorisations and solves on different threads take turns for BLAS: true unless the
// process loaded a BLAS that is safe for concurrent callers (Debian's threaded OpenBLAS, told
// to use one thread a call). dda fos runs its trials on threads.
bool blas_calls_serialised();

// A symmetric rank-one term sign * c c^T, c sparse: (row, value) pairs.
struct RankOneTerm {
  std::vector<std::pair<int, double>> entries;
};

// What rebuilds a SparseCholesky's factor bit for bit (a checkpoint's kept factor,
// docs/checkpoint.md): the analysed pattern, the matrix last factorised in it, and the
// rank-one modifications applied since, in order. Analysis and numeric factorisation are
// deterministic for a given pattern and matrix, and cholmod_updown for a given factor and
// terms, so replaying these on a fresh object makes the same factor, the same cost tables
// and therefore the same later choices; storing CHOLMOD's factor itself would mean writing
// its simplicial and supernodal layouts field by field.
struct FactorModification {
  bool update = true;  // K += c c^T (else K -= c c^T)
  std::vector<RankOneTerm> terms;
};
struct FactorRecord {
  bool analysed = false;         // a pattern was analysed (else nothing below matters)
  std::vector<int> outer;        // the analysed pattern (lower triangle, compressed columns)
  std::vector<int> inner;
  std::vector<double> values;    // the matrix last factorised, in that pattern
  bool factored = false;         // that factorisation (and the modifications) succeeded
  int analyses = 0;              // the count analyses() reports
  std::vector<FactorModification> modifications;  // since that factorisation
};

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Factorises the symmetric matrix given by its lower triangle. False when it is not
  // positive definite. The analysis (ordering and symbolic factor) is kept on a pattern that
  // survives contact changes: a matrix whose entries all lie in the
  // analysed pattern is factorised on it, with explicit zeros where it has none; one with an
  // entry outside is analysed again, on the union of the two patterns, as long as that has
  // at most kPatternSlack more entries than the matrix (else on the matrix's own pattern).
  // Orderings: AMD, and for large systems (at least kNestedDissectionRows rows) METIS nested
  // dissection as well, the one with the smaller factor kept.
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  static constexpr double kPatternSlack = 0.1;
  // Analyses made since construction.
  int analyses() const { return analyses_; }
  // On the 1000-brick wall (6000 rows) AMD's factor is the smaller (6.9e7 flops against
  // METIS's 8.9e7) and its analysis 3 ms against 9 ms; at 10000 bricks (60000 rows) a
  // factorisation with METIS takes 0.27-0.32 s supernodal on one core
  // (measured), so both are tried there and CHOLMOD keeps the one with fewer entries.
  static constexpr int kNestedDissectionRows = 20000;

  // K += c c^T for every term (update = true) or K -= c c^T (update = false). False when the
  // result is not positive definite (the factor is then unusable until factorize()).
  bool modify(const std::vector<RankOneTerm>& terms, bool update);

  // A cost model of the ways to an answer, in modelled nanoseconds of one core of the
  // machine it was fitted on (2-core AMD EPYC, Debian's serial OpenBLAS). Deterministic:
  // computed from the structure of the last factorisation (tables made once per
  // factorisation), so a run's path does
  // not depend on the machine's timing. Fitted on the brick walls' systems, 100 to 10000
  // bricks (docs/linear-solver.md, "Cost model", has the measurements):
  //  - refactorisation_cost(): a simplicial LDL' is a left-looking sweep at a flat
  //    2.5 GFlop/s, kSimplicialFlopNs x sum over columns j of nnz(L(:,j))^2 (its flop
  //    count). A supernodal LL' runs dense BLAS kernels whose rate grows with the flops per
  //    factor entry (2.8 GFlop/s at 300 bricks, 15 at 10000), which makes its time about
  //    kSupernodalEntryNs x nnz(L) at every size measured (2.7, 12, 50, 220 ms at 300, 1000,
  //    3000, 10000 bricks); the smaller of the two models.
  //  - modification_cost(terms): for each rank-one term, kUpdateEntryNs x the sum of
  //    nnz(L(:,j)) over the columns j that cholmod_updown visits, the elimination-tree path
  //    from the term's first row (in the factor's order) to the root. (Updates add fill, so
  //    later ones cost a little more than the model says.)
  //  - solve_cost(): two triangular sweeps over nnz(L), memory bound: 0.4 ns an entry while
  //    the factor fits in cache, rising to 1 ns from nnz(L) = 5e6 (60 MB) on.
  double refactorisation_cost() const;
  double modification_cost(const std::vector<RankOneTerm>& terms) const;
  double solve_cost() const;
  static constexpr double kSimplicialFlopNs = 0.4;
  static constexpr double kSupernodalEntryNs = 27.0;
  static constexpr double kUpdateEntryNs = 1.0;

  // Solves with the present factor. Requires a successful factorize().
  Eigen::VectorXd solve(const Eigen::VectorXd& b);

  bool has_factor() const { return factor_ != nullptr && factored_; }

  // The state to rebuild this factor from, and the rebuild (on any object: what it held is
  // dropped). restore() returns false when the replay does not end as the record says (a
  // record of another build of CHOLMOD or BLAS); the object then holds no factor, and the
  // next factorize() starts afresh.
  FactorRecord record() const;
  bool restore(const FactorRecord& record);
  bool supernodal() const { return factor_ != nullptr && factor_->is_super; }

 private:
  bool same_pattern(const Eigen::SparseMatrix<double>& k) const;
  // Puts k's values into the analysed pattern (values_); false when k has an entry outside.
  bool scatter_into_pattern(const Eigen::SparseMatrix<double>& k);
  // The pattern to analyse next: k's, with the present one's entries while they are few.
  void grow_pattern(const Eigen::SparseMatrix<double>& k);
  cholmod_sparse view_pattern() const;  // outer_, inner_, values_ as CHOLMOD reads them
  bool positive_pivots() const;
  // The ordering and symbolic factor of pattern `a` (AMD; AMD and METIS from
  // kNestedDissectionRows rows on) into symbolic_; false when CHOLMOD fails.
  bool analyse(cholmod_sparse& a);
  void make_cost_tables();

  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  // solve()'s answer and workspaces (cholmod_solve2), kept between calls: a Krylov
  // iteration on the kept factor is one solve, and allocating three vectors for each was a
  // noticeable share of it on small systems.
  cholmod_dense* solve_x_ = nullptr;
  cholmod_dense* solve_y_ = nullptr;
  cholmod_dense* solve_e_ = nullptr;
  cholmod_factor* symbolic_ = nullptr;  // the analysis of the present pattern, kept
  std::vector<int> outer_;  // the analysed pattern (lower triangle, compressed columns)
  std::vector<int> inner_;
  std::vector<double> values_;  // a matrix scattered into it
  int analyses_ = 0;
  std::vector<int> inverse_perm_;  // row i of A is row inverse_perm_[i] of P A
  // The analysed pattern permuted as the factor needs it, made once per analysis, so that
  // CHOLMOD factorises it as given instead of transposing the matrix into it at every
  // factorisation (cholmod_factorize permutes and transposes a matrix it is handed in the
  // original order: a copy of every entry, 5 % of the 150-square box's run). A simplicial
  // LDL' reads the upper triangle of P K P' by columns, a supernodal LL' the lower one.
  // permuted_position_[q]: where entry q of the analysed pattern goes.
  void make_permuted_layout();
  std::vector<int> permuted_outer_;
  std::vector<int> permuted_inner_;
  std::vector<int> permuted_position_;
  std::vector<double> permuted_values_;
  bool permuted_sorted_ = true;  // each column's rows in order (as CHOLMOD marks it)
  // The cost model's tables, made at the first factorisation after an analysis (the
  // factor's structure is the analysis's until the next one): for each column j of L
  // (factor's order), the summed column counts from j up the elimination tree to the root;
  // and sum nnz^2.
  bool tables_made_ = false;
  std::vector<double> path_cost_;
  double column_count_squares_ = 0.0;  // sum over columns of nnz(L(:,j))^2
  double factor_entries_ = 0.0;  // nnz(L) of the last factorisation
  bool factored_ = false;
  bool modified_ = false;  // converted to simplicial LDL' and updated since factorised
  std::vector<FactorModification> modifications_;  // since the last factorisation (record())
};

}  // namespace dda
