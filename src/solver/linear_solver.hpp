// Linear solves of the assembled system: CHOLMOD (the fast path) and a dense LDLT (the simple
// reference that tests compare it with).
#pragma once

#include <Eigen/Sparse>
#include <optional>
#include <utility>
#include <vector>

#include "solver/block_system.hpp"
#include "solver/sparse_cholesky.hpp"

namespace dda {

// Dense reference: LDLT of the whole matrix. nullopt when the matrix is not positive definite.
std::optional<Eigen::VectorXd> solve_dense(const BlockSystem& system);

// Sparse LU with KLU for the unsymmetric system (a non-associated plastic block's tangent):
// analysed and factorised at every call. nullopt when the matrix is singular.
std::optional<Eigen::VectorXd> solve_klu(const BlockSystem& system);

// y = K x for the symmetric block system (diagonal blocks plus couplings both ways), x and
// y in the reduced layout of its dof map (BlockSystem: a rigid block's strain slots dropped).
Eigen::VectorXd multiply(const BlockSystem& system, const Eigen::VectorXd& x);

// What CholmodSolver did (counts since construction).
struct LinearSolveStats {
  int factorisations = 0;  // numeric factorisations (plain path, fallbacks, refreshes)
  int analyses = 0;        // symbolic analyses (orderings) among them: new patterns
  int modifications = 0;   // factors updated by rank-one springs
  int reused = 0;          // answers by conjugate gradients on the kept factor
  long cg_iterations = 0;  // their iterations
  int cg_failures = 0;     // CG runs that did not converge in their cap (then factorised)
  // With CholmodSolver::check_against_plain: the largest relative difference between a
  // reused or modified factor's answer and a fresh factorisation's of the same system.
  double largest_difference_from_plain = 0.0;
};

// Sparse Cholesky with CHOLMOD, and three ways of not factorising:
//  - solve(): the plain path: factorise and solve; the symbolic analysis is kept while the
//    sparsity pattern is unchanged (a scene without contacts keeps it for the whole run).
//  - solve_reusing(): the system is close to the one last factorised (the next step, a
//    finite_rotation secant that moved, a plastic tangent): conjugate gradients
//    preconditioned by the kept factor, which converges in a few iterations when the two
//    matrices differ little (in exact arithmetic, in at most rank(K - F) + 1). If CG does not
//    converge within its cap, or the last CG needed more than half of it (the matrix has
//    drifted from the factor), the system is factorised.
//  - solve_modified(): the system differs from the kept factor's matrix by the springs
//    `added` (now present) and `removed` (gone; FactorSprings finds both) and by a small
//    drift: the factor is updated and downdated in place (rank one per spring) when the cost
//    model says that is cheaper than factorising, and the answer taken by CG on the updated
//    factor, as solve_reusing does (which it is when there are no springs to change).
// With reuse off (set_reuse(false)) every call is the plain path: the reference that tests
// compare the fast paths with.
class CholmodSolver {
 public:
  // How the last answer was found.
  enum class Path { Factorised, Modified, Reused };

  // nullopt when the matrix is not positive definite.
  std::optional<Eigen::VectorXd> solve(const BlockSystem& system);
  std::optional<Eigen::VectorXd> solve_reusing(const BlockSystem& system);
  std::optional<Eigen::VectorXd> solve_modified(const BlockSystem& system,
                                                const std::vector<RankOneTerm>& added,
                                                const std::vector<RankOneTerm>& removed);

  // The unsymmetric system (K + sum_j u_j v_j^T) x = b, with K = `system` (symmetric, and
  // the matrix of the last answer: the factor is the one that answer was found with) and the
  // pairs (u_j, v_j) in the solvers' layout: GMRES preconditioned on the right by the kept
  // factor (Saad, Iterative Methods for Sparse Linear Systems, 2003, alg. 9.5). A low-rank
  // term costs about one iteration a term, as CG's changed springs do. nullopt when it has
  // not converged within kGmresMaxIterations.
  // It stops when the residual has fallen below `tolerance` times |b|. With `start`, GMRES
  // solves for the change from it (the residual b - A start), and start + change is returned.
  std::optional<Eigen::VectorXd> solve_low_rank_coupled(const BlockSystem& system,
                                                        const Eigen::VectorXd& b,
                                                        const std::vector<RankOneTerm>& u,
                                                        const std::vector<RankOneTerm>& v,
                                                        double tolerance,
                                                        const Eigen::VectorXd* start = nullptr);
  // The residual share an answer is taken at (the CG tolerance's energy-norm share, as a
  // plain norm), and the share an iterate of the Newton contact solver is corrected to: its
  // modes are read off the answer, and a mode decided by a gap that 1e-3 of the correction
  // moves across the contact resolution comes back at the next solve anyway (an inexact
  // Newton step). On the 1000-brick wall, whose settling keeps 300 contacts sliding, GMRES
  // was half the time at 1e-12, and 70 % of the solves' time at 1e-6 (10 iterations a
  // solve, each a solve with a 6000-unknown factor); at 1e-3 the first 30 steps take 3.95 s
  // instead of 5.0 with the same number of solves, the box of 150 squares 3.5 s instead of
  // 3.8. (1e-2 and 1e-4 were both slower: more solves, or more iterations.)
  static constexpr double kGmresTolerance = 1e-12;
  static constexpr double kGmresTrialTolerance = 1e-3;
  static constexpr int kGmresMaxIterations = 120;

  void set_reuse(bool reuse) { reuse_ = reuse; }
  // Verification: every answer not from a fresh factorisation is compared with one (a second
  // factor, so the fast path's own state is untouched); the largest relative difference is
  // kept in stats(). Costs a factorisation per solve: tests only.
  void set_check_against_plain(bool check) { check_ = check; }

  // The cost model of solve_modified and of the refresh below: SparseCholesky's modelled
  // nanoseconds (refactorisation, rank-one modification, solve with the factor) plus
  // kProductNs per multiply-add of a product with K. (It once counted
  // multiply-adds, which priced a supernodal factorisation by its flops: 170 CG iterations'
  // worth at 10000 bricks where it takes 10, so the factor drifted until CG took 19
  // iterations a step.)
  static constexpr double kProductNs = 0.5;
  // CG iterations taken for the drift of the matrix from the factor's besides the changed
  // springs (2 to 4 on the walls a step after the factor was made).
  static constexpr double kExpectedCgIterations = 3.0;

  // CG stops when the preconditioned residual r' F^-1 r has fallen below kCgTolerance^2 of
  // its start b' F^-1 b. With F close to K these are the squared energy norms of the error
  // and of the answer, so the answer is within 1e-13 of the exact one in energy norm; a
  // contact's gap is then exact far below the contact resolution 1e-5 x allowed_penetration
  // that decides modes. 1e-10 would do for that, but the hard-case column (20 squares
  // dropped onto each other, symmetric) amplifies any asymmetry of the answers: with 1e-10
  // it drifted sideways 5 mm in 1 s, with 1e-13 2.3 mm, with fresh factorisations 1 mm (its
  // check allows 2.5 mm). CG on a settled wall takes 2 to 3 iterations either way.
  static constexpr double kCgTolerance = 1e-13;
  // CG's cap: the iterations that cost as much as a factorisation (by the model above), kept
  // within [kCgMinIterations, kCgMaxIterations]. Not knowing how many iterations a CG will
  // need, stopping it where it has cost one factorisation spends at most twice what the
  // better choice would have (the rent-or-buy argument); ~10 at 10000 bricks, ~20 at 1000.
  static constexpr double kCgShareOfRefactor = 1.0;
  static constexpr int kCgMinIterations = 4;
  static constexpr int kCgMaxIterations = 60;

  // The refresh: a kept factor drifts from the matrices it preconditions, and CG takes more
  // iterations from step to step. The cost per solve since the last factorisation (its cost
  // plus every modification and CG iteration since) is least when a solve's CG costs as
  // much as that average: after a CG that cost more, the next reuse factorises.

  // What a checkpoint keeps of the solver (docs/checkpoint.md): the kept factor (as
  // SparseCholesky::record rebuilds it), the refresh rule's counters and the counts, so that
  // a run continued from a checkpoint takes the same paths to the same answers, bit for bit,
  // as the run never stopped.
  struct Record {
    FactorRecord factor;
    int factored_rows = -1;
    bool refresh = false;
    double since_factor_cost = 0.0;
    int since_factor_solves = 0;
    Path last_path = Path::Factorised;
    LinearSolveStats stats;
  };
  Record record() const;
  // False when the factor could not be rebuilt: the solver then holds none and factorises
  // at its next solve (a continued run then agrees with the unbroken one to the solver's
  // tolerance, not bit for bit).
  bool restore(const Record& record);

  int factorisations() const { return stats_.factorisations; }
  int modifications() const { return stats_.modifications; }
  const LinearSolveStats& stats() const { return stats_; }
  Path last_path() const { return last_path_; }

 private:
  // Conjugate gradients on `system` preconditioned by the present factor; nullopt when it
  // does not converge within the cap.
  std::optional<Eigen::VectorXd> conjugate_gradients(const BlockSystem& system);
  // The answer by CG on the present factor, recorded as found by `path`; a fresh
  // factorisation when CG does not converge.
  std::optional<Eigen::VectorXd> answer_by_cg(const BlockSystem& system, Path path);
  int cg_cap(const BlockSystem& system) const;
  double cg_iteration_cost(const BlockSystem& system) const;  // multiply-adds
  void compare_with_plain(const BlockSystem& system, const Eigen::VectorXd& x);

  SparseCholesky factor_;
  int factored_rows_ = -1;
  bool reuse_ = true;
  bool check_ = false;
  bool refresh_ = false;  // the last CG cost more than the average: factorise at next reuse
  double since_factor_cost_ = 0.0;  // modelled ns since the last factorisation, and solves
  int since_factor_solves_ = 0;
  Path last_path_ = Path::Factorised;
  LinearSolveStats stats_;
  // GMRES's Hessenberg matrix, kept between calls: each call fills only the columns it
  // reaches (a few), and a fresh zeroed (kGmresMaxIterations + 1)^2 matrix a call had made
  // zeroing memory 4 % of the 150-square box's instructions.
  Eigen::MatrixXd hessenberg_;
};

}  // namespace dda
