// The fast path (CHOLMOD) against the simple reference (dense LDLT) on assembled systems.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>
#include <random>

#include "../../bench/brick_wall.hpp"
#include "kinematics/block_matrices.hpp"
#include "support/scene_builders.hpp"
#include "solver/assembly.hpp"
#include "solver/linear_solver.hpp"
#include "solver/step.hpp"
#include "solver/workspace_record.hpp"
#include "solver/world.hpp"

using namespace dda;

namespace {

// A world of `n` blocks of assorted shapes with pins and point loads, some fixed.
World assorted_world(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Scene s = test::base_scene(1, 0.01);
  s.materials.push_back(elastic_material("soft", 1800.0, 5e7, 0.3));
  for (int i = 0; i < n; ++i) {
    const Vec2 c(3.0 * i, 0.0);
    BlockSpec b = test::block(i % 3 == 0   ? test::regular_polygon(5 + i % 4, 0.8, c, u(rng))
                              : i % 3 == 1 ? test::rectangle(c.x() - 1, -0.5, 2, 1 + 0.5 * u(rng))
                                           : Polygon{{c.x() - 1, -1}, {c.x() + 1, -1}, {c.x() + 1, 0},
                                                     {c.x(), 0}, {c.x(), 1}, {c.x() - 1, 1}});
    b.material = i % 2;
    b.fixed = (i % 7 == 6);
    b.velocity = Vec3(u(rng), u(rng), u(rng));
    b.initial_stress = 1e5 * Vec3(u(rng), u(rng), u(rng));
    s.blocks.push_back(b);
    if (i % 4 == 1) s.pins.push_back(PinSpec{{c.x() + 0.2, 0.1}, i});
    if (i % 5 == 2) s.point_loads.push_back(PointLoadSpec{{c.x(), 0.2}, {1e4 * u(rng), 1e4}, i});
  }
  return make_world(s);
}

// Springs between neighbouring free blocks, as contacts will add: p [Ti -Tj]^T [Ti -Tj].
void add_block_couplings(const World& w, BlockSystem& sys, double p) {
  const LinearT t = shi_t();
  for (std::size_t i = 0; i + 1 < w.blocks.size(); ++i) {
    const Block& a = w.blocks[i];
    const Block& b = w.blocks[i + 1];
    if (a.fixed || b.fixed) continue;
    const Vec2 x = 0.5 * (a.moments.centroid + b.moments.centroid);
    const Mat26 ta = t.at(x - a.moments.centroid);
    const Mat26 tb = t.at(x - b.moments.centroid);
    sys.diagonal[block_row(a)] += p * ta.transpose() * ta;
    sys.diagonal[block_row(b)] += p * tb.transpose() * tb;
    sys.couplings.push_back({block_row(b), block_row(a), -p * tb.transpose() * ta});
  }
}

StepContext context(const World& w, double dt) {
  StepContext ctx;
  ctx.dt = dt;
  ctx.penalty = w.penalty;
  ctx.dynamic_coefficient = 1.0;
  return ctx;
}

}  // namespace

TEST_CASE("CHOLMOD and dense LDLT agree on assembled systems", "[solver]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    World w = assorted_world(25, seed);
    BlockSystem sys;
    assemble(w, context(w, 0.01), sys);
    add_block_couplings(w, sys, 1e9);
    const auto dense = solve_dense(sys);
    CholmodSolver cholmod;
    const auto sparse = cholmod.solve(sys);
    REQUIRE(dense);
    REQUIRE(sparse);
    // Both are backward-stable factorisations of the same SPD matrix (condition ~1e8 with
    // the penalty springs): they agree to well within 1e-10 relative, the agreement asked of them.
    CHECK((*dense - *sparse).norm() <= 1e-10 * dense->norm());
    // And the sparse answer satisfies the system (residual relative to K and x).
    const Eigen::MatrixXd k = sys.dense();
    CHECK((k * *sparse - sys.rhs).norm() <= 1e-12 * k.norm() * sparse->norm());
  }
}

TEST_CASE("CHOLMOD reuses its analysis and follows a changed pattern", "[solver]") {
  World w = assorted_world(12, 7);
  BlockSystem sys;
  CholmodSolver cholmod;
  assemble(w, context(w, 0.01), sys);
  const auto first = cholmod.solve(sys);
  assemble(w, context(w, 0.005), sys);  // same pattern, new values
  const auto second = cholmod.solve(sys);
  add_block_couplings(w, sys, 1e9);  // new pattern
  const auto third = cholmod.solve(sys);
  REQUIRE((first && second && third));
  assemble(w, context(w, 0.005), sys);
  CHECK((*second - *solve_dense(sys)).norm() <= 1e-10 * second->norm());
  add_block_couplings(w, sys, 1e9);
  CHECK((*third - *solve_dense(sys)).norm() <= 1e-10 * third->norm());
}

TEST_CASE("a matrix that is not positive definite is reported, not solved", "[solver]") {
  BlockSystem sys;
  sys.reset(1);
  sys.diagonal[0] = -Mat6::Identity();
  sys.rhs.setOnes();
  CholmodSolver cholmod;
  CHECK_FALSE(cholmod.solve(sys));
  CHECK_FALSE(solve_dense(sys));
}

TEST_CASE("a factor updated by rank-one springs solves like a fresh factorisation", "[solver]") {
  // The open-close loop changes K by the springs of contacts that changed mode; the factor is
  // updated and downdated in place. Reference: dense LDLT of the new matrix.
  World w = assorted_world(12, 11);
  BlockSystem sys;
  assemble(w, context(w, 0.01), sys);
  add_block_couplings(w, sys, 1e9);  // springs between neighbours
  Eigen::SparseMatrix<double> lower = sys.lower_triangle();
  lower.makeCompressed();
  SparseCholesky factor;
  REQUIRE(factor.factorize(lower));

  // A new spring p c c^T between blocks 1 and 2.
  const LinearT t = shi_t();
  const Block& a = w.blocks[1];
  const Block& b = w.blocks[2];
  REQUIRE((!a.fixed && !b.fixed));
  const Vec2 x = 0.5 * (a.moments.centroid + b.moments.centroid);
  const Vec6 ca = std::sqrt(3e9) * t.at(x - a.moments.centroid).transpose() * Vec2(0.6, 0.8);
  const Vec6 cb = -std::sqrt(3e9) * t.at(x - b.moments.centroid).transpose() * Vec2(0.6, 0.8);
  RankOneTerm term;
  for (int i = 0; i < 6; ++i) {
    term.entries.emplace_back(a.first_dof + i, ca[i]);
    term.entries.emplace_back(b.first_dof + i, cb[i]);
  }
  Eigen::MatrixXd k_new = sys.dense();
  for (const auto& [ri, vi] : term.entries) {
    for (const auto& [rj, vj] : term.entries) k_new(ri, rj) += vi * vj;
  }
  REQUIRE(factor.modify({term}, true));
  const Eigen::VectorXd reference = Eigen::LDLT<Eigen::MatrixXd>(k_new).solve(sys.rhs);
  // Update and solve are backward stable like the factorisation: 1e-10 as for CHOLMOD vs dense.
  CHECK((factor.solve(sys.rhs) - reference).norm() <= 1e-10 * reference.norm());

  // And back: downdating the same spring returns the first system's solution.
  REQUIRE(factor.modify({term}, false));
  const Eigen::VectorXd first = *solve_dense(sys);
  CHECK((factor.solve(sys.rhs) - first).norm() <= 1e-10 * first.norm());
}

TEST_CASE("KLU solves an unsymmetric block system like a dense LU", "[solver]") {
  // Diagonal blocks made unsymmetric (as a non-associated tangent makes them), couplings
  // mirrored as in the symmetric system; diagonally dominant so the LU is well conditioned
  // (condition ~10): both answers agree to round-off, 1e-12 of |x|.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BlockSystem s;
  s.reset(5);
  for (Mat6& d : s.diagonal) {
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) d(i, j) = u(rng);
    }
    d += 20.0 * Mat6::Identity();
  }
  for (int r = 1; r < 5; ++r) {
    BlockSystem::Coupling c{r, r - 1, Mat6::Zero()};
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) c.k(i, j) = u(rng);
    }
    s.couplings.push_back(c);
  }
  for (int i = 0; i < s.rhs.size(); ++i) s.rhs[i] = u(rng);
  const std::optional<Eigen::VectorXd> x = solve_klu(s);
  REQUIRE(x.has_value());
  const Eigen::VectorXd reference = s.dense().partialPivLu().solve(s.rhs);
  CHECK((*x - reference).norm() <= 1e-12 * reference.norm());
  // And the residual of the assembled system itself.
  CHECK((multiply(s, *x) - s.rhs).norm() <= 1e-12 * s.rhs.norm());
}

namespace {

// The system of the last open-close iteration of a brick wall (bench/brick_wall.hpp) after
// `steps` steps: contacts, penalty springs, finite_rotation's T.
BlockSystem settling_wall_system(int bricks, int steps) {
  World world = make_world(bench::brick_wall_scene(bricks, elastic_material("rock", 2700.0, 1e9, 0.25)));
  StepWorkspace ws;
  RunStats stats;
  for (int k = 0; k < steps; ++k) REQUIRE(advance_step(world, ws, stats).ok);
  return ws.system;
}

}  // namespace

TEST_CASE("conjugate gradients on a kept factor solve a changed system like LDLT", "[solver]") {
  // The kept factor is that of the system K; the new system is K + a spring between two
  // blocks (rank one) with all values scaled by 1 +- 1e-4 (a step later, T and the contact
  // geometry moved a little). CG preconditioned by the old factor needs a few iterations,
  // and its answer meets the energy-norm tolerance 1e-13 (kCgTolerance): within 1e-8 of
  // dense LDLT in the 2-norm (the 2-norm error may exceed the energy-norm one by the square
  // root of the condition, ~1e4 with the penalty springs, and dense LDLT's own error is
  // ~1e-16 x condition ~1e-8; measured ~1e-12).
  World w = assorted_world(25, 5);
  BlockSystem sys;
  assemble(w, context(w, 0.01), sys);
  add_block_couplings(w, sys, 1e9);
  CholmodSolver cholmod;
  REQUIRE(cholmod.solve(sys));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1e-6, 1e-6);
  BlockSystem moved = sys;
  for (Mat6& d : moved.diagonal) d *= 1.0 + u(rng);
  for (BlockSystem::Coupling& c : moved.couplings) c.k *= 1.0 + u(rng);
  const auto x = cholmod.solve_reusing(moved);
  REQUIRE(x);
  CHECK(cholmod.stats().factorisations == 1);  // no new factorisation
  CHECK(cholmod.stats().reused == 1);
  // A drift of 1e-6 shrinks the preconditioned residual by ~1e-6 an iteration: 3 reach
  // 1e-13 (the cap of so small a system is 4 iterations).
  CHECK(cholmod.stats().cg_iterations <= 4);
  const Eigen::VectorXd reference = *solve_dense(moved);
  CHECK((*x - reference).norm() <= 1e-8 * reference.norm());

  // A system far from the factor's (every diagonal block doubled, couplings halved): CG does
  // not converge within its cap, and the solver factorises instead: the answer is exact.
  BlockSystem far = sys;
  for (Mat6& d : far.diagonal) d *= 2.0;
  for (BlockSystem::Coupling& c : far.couplings) c.k *= -0.5;
  far.rhs.setRandom();
  const auto y = cholmod.solve_reusing(far);
  REQUIRE(y);
  const Eigen::VectorXd far_reference = *solve_dense(far);
  CHECK((*y - far_reference).norm() <= 1e-10 * far_reference.norm());
  CHECK(cholmod.stats().factorisations + cholmod.stats().cg_failures >= 2);

  // With reuse off every call is the plain path.
  CholmodSolver plain;
  plain.set_reuse(false);
  REQUIRE(plain.solve(sys));
  REQUIRE(plain.solve_reusing(moved));
  CHECK(plain.stats().factorisations == 2);
  CHECK(plain.stats().reused == 0);
}

TEST_CASE("the supernodal factor of a wall's system agrees with dense LDLT, updated or not",
          "[solver]") {
  // 400 bricks (2400 unknowns): CHOLMOD's automatic choice is the supernodal LL' here (about
  // 60 flops per factor entry). Its answer, the answer after rank-one springs (which converts
  // it to a simplicial LDL'), and the answer of a refactorisation afterwards (which starts
  // again from the kept supernodal analysis) all agree with dense LDLT to 1e-10 relative, as
  // CHOLMOD against dense above.
  const BlockSystem sys = settling_wall_system(400, 3);
  CholmodSolver cholmod;
  const auto x = cholmod.solve(sys);
  REQUIRE(x);
  const Eigen::VectorXd reference = *solve_dense(sys);
  CHECK((*x - reference).norm() <= 1e-10 * reference.norm());

  SparseCholesky factor;
  Eigen::SparseMatrix<double> lower = sys.lower_triangle();
  lower.makeCompressed();
  REQUIRE(factor.factorize(lower));
  CHECK(factor.supernodal());
  // One spring p c c^T between the unknowns of blocks 3 and 4 (u0 of one, v0 of the other).
  RankOneTerm term;
  term.entries = {{6 * 3 + 0, 3e4}, {6 * 4 + 1, -3e4}};
  REQUIRE(factor.modify({term}, true));
  CHECK_FALSE(factor.supernodal());
  Eigen::MatrixXd k = sys.dense();
  for (const auto& [ri, vi] : term.entries) {
    for (const auto& [rj, vj] : term.entries) k(ri, rj) += vi * vj;
  }
  const Eigen::VectorXd updated = Eigen::LDLT<Eigen::MatrixXd>(k).solve(sys.rhs);
  const Eigen::VectorXd from_update = factor.solve(sys.rhs);
  CHECK((from_update - updated).norm() <= 1e-10 * updated.norm());
  REQUIRE(factor.factorize(lower));
  CHECK(factor.supernodal());
  CHECK((factor.solve(sys.rhs) - reference).norm() <= 1e-10 * reference.norm());
}

namespace {

// CHOLMOD's own way, the reference: the lower triangle in the original order, analysed and
// factorised as SparseCholesky::analyse sets it up (AMD alone below 20 000 rows, automatic
// simplicial or supernodal, LDL' kept), cholmod_factorize permuting the matrix itself.
Eigen::VectorXd cholmod_own_answer(Eigen::SparseMatrix<double> lower, const Eigen::VectorXd& b,
                                   bool& supernodal) {
  lower.makeCompressed();
  cholmod_common c;
  cholmod_start(&c);
  c.supernodal = CHOLMOD_AUTO;
  c.final_ll = 0;
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_AMD;
  cholmod_sparse a{};
  a.nrow = a.ncol = static_cast<size_t>(lower.rows());
  a.nzmax = static_cast<size_t>(lower.nonZeros());
  a.p = lower.outerIndexPtr();
  a.i = lower.innerIndexPtr();
  a.x = lower.valuePtr();
  a.stype = -1;
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  cholmod_factor* l = cholmod_analyze(&a, &c);
  cholmod_factorize(&a, l, &c);
  supernodal = l->is_super;
  cholmod_dense rhs{};
  rhs.nrow = rhs.nzmax = rhs.d = static_cast<size_t>(b.size());
  rhs.ncol = 1;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, l, &rhs, &c);
  const Eigen::VectorXd answer = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(x->x), b.size());
  cholmod_free_dense(&x, &c);
  cholmod_free_factor(&l, &c);
  cholmod_finish(&c);
  return answer;
}

}  // namespace

TEST_CASE("a factor of the matrix handed over in the factor's order is CHOLMOD's own bit for bit",
          "[solver]") {
  // SparseCholesky places the values straight into the permuted layout made at the analysis
  // and lets CHOLMOD factorise them as given; CHOLMOD's own way permutes (and transposes) the
  // matrix at every factorisation. The entries stand in the order CHOLMOD's permutation
  // gives them, so the arithmetic is the same to the last bit: compared with ==, for a
  // simplicial LDL' (30 bricks) and a supernodal LL' (400 bricks), factorised twice (the
  // second time in place on the kept analysis).
  for (const int bricks : {30, 400}) {
    const BlockSystem sys = settling_wall_system(bricks, 3);
    Eigen::SparseMatrix<double> lower = sys.lower_triangle();
    lower.makeCompressed();
    bool supernodal = false;
    const Eigen::VectorXd reference = cholmod_own_answer(lower, sys.rhs, supernodal);
    SparseCholesky factor;
    REQUIRE(factor.factorize(lower));
    CHECK(factor.supernodal() == supernodal);
    CHECK(supernodal == (bricks == 400));
    CHECK(factor.solve(sys.rhs) == reference);
    REQUIRE(factor.factorize(lower));
    CHECK(factor.solve(sys.rhs) == reference);
  }
}

TEST_CASE("the fast linear paths give the plain path's answers on a settling wall", "[solver]") {
  // Every fast path (CG on a kept factor, rank-one updates with CG on top) against
  // the plain factorise-and-solve of the same system, at every solve of 120 steps of a
  // 100-brick wall settling under gravity (contacts close, slide and lock meanwhile). The
  // answers differ by at most 1e-8 relative (the CG tolerance is 1e-13 in energy norm; see
  // the first CG test for the 2-norm). Then the whole run against a run on the plain path:
  // the same steps, the same contacts, and brick positions within 1e-9 m (the per-solve
  // differences, ~1e-11 of motions of ~1e-4 m, do not add up to more over 120 steps).
  const Scene scene = bench::brick_wall_scene(100, elastic_material("rock", 2700.0, 1e9, 0.25));
  Scene plain_scene = scene;
  plain_scene.control.reuse_factor = false;  // "linear_solver": "factorise"
  World fast = make_world(scene);
  World plain = make_world(plain_scene);
  StepWorkspace fast_ws, plain_ws;
  fast_ws.solver.set_check_against_plain(true);
  RunStats fast_stats, plain_stats;
  for (int k = 0; k < 120; ++k) {
    REQUIRE(advance_step(fast, fast_ws, fast_stats).ok);
    REQUIRE(advance_step(plain, plain_ws, plain_stats).ok);
  }
  const LinearSolveStats& s = fast_ws.solver.stats();
  INFO("factorisations " << s.factorisations << ", reused " << s.reused << ", modified "
                         << s.modifications << ", CG iterations " << s.cg_iterations);
  INFO("plain path: " << plain_ws.solver.stats().factorisations << " factorisations");
  CHECK(s.reused >= 100);  // the paths under test were taken
  CHECK(s.factorisations < plain_ws.solver.stats().factorisations);
  CHECK(s.largest_difference_from_plain <= 1e-8);
  // The contact solver's iterates take the friction coupling's correction to 1e-6 only
  // (CholmodSolver::kGmresTrialTolerance), so the two paths, whose solves differ by ~1e-11,
  // may read a mode an iteration apart on the way; the answers a step accepts are refined to
  // 1e-12 and agree (the positions below). Measured 396 solves against 394: within 1 %.
  CHECK(std::abs(fast_stats.open_close_total - plain_stats.open_close_total) <=
        plain_stats.open_close_total / 100);
  CHECK(fast.contacts.size() == plain.contacts.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < fast.blocks.size(); ++i) {
    for (std::size_t v = 0; v < fast.blocks[i].vertices.size(); ++v) {
      largest = std::max(largest, (fast.blocks[i].vertices[v] - plain.blocks[i].vertices[v]).norm());
    }
  }
  CHECK(largest <= 1e-9);
}

TEST_CASE("solve_modified chooses update, CG or factorisation by the modelled cost", "[solver]") {
  // On a 400-brick wall's system (2400 unknowns): one changed spring costs far less to
  // update (or to leave to CG) than a factorisation, so the factor is kept; 1500 springs
  // between distinct block pairs would need ~1500 CG iterations or as many updates, more
  // than a factorisation, so the system is factorised. Every answer agrees with dense LDLT
  // of the modified matrix to 1e-8 (CG's tolerance, as in the CG test above).
  const BlockSystem sys = settling_wall_system(400, 3);
  for (int springs : {1, 1500}) {
    INFO(springs << " changed springs");
    std::vector<RankOneTerm> added;
    Eigen::MatrixXd k = sys.dense();
    for (int s = 0; s < springs; ++s) {
      // Block rows r and r + 1: u0 of one against v0 of the other, stiffness 9e8.
      const int r = s % (sys.block_rows() - 1);
      RankOneTerm term;
      term.entries = {{6 * r, 3e4}, {6 * (r + 1) + 1, -3e4 * (1.0 + s / 1500.0)}};
      for (const auto& [ri, vi] : term.entries) {
        for (const auto& [rj, vj] : term.entries) k(ri, rj) += vi * vj;
      }
      added.push_back(term);
    }
    BlockSystem modified = sys;
    for (int r = 0; r < modified.block_rows(); ++r) modified.diagonal[r] = k.block<6, 6>(6 * r, 6 * r);
    for (BlockSystem::Coupling& c : modified.couplings) c.k = k.block<6, 6>(6 * c.row, 6 * c.col);
    // Couplings the springs add where the system had none.
    for (int r = 0; r + 1 < modified.block_rows(); ++r) {
      bool coupled = false;
      for (const BlockSystem::Coupling& c : modified.couplings) coupled |= (c.row == r + 1 && c.col == r);
      if (!coupled && !k.block<6, 6>(6 * (r + 1), 6 * r).isZero(0.0)) {
        modified.couplings.push_back({r + 1, r, k.block<6, 6>(6 * (r + 1), 6 * r)});
      }
    }
    CholmodSolver cholmod;
    REQUIRE(cholmod.solve(sys));
    const auto x = cholmod.solve_modified(modified, added, {});
    REQUIRE(x);
    if (springs == 1) {
      CHECK(cholmod.last_path() != CholmodSolver::Path::Factorised);
      CHECK(cholmod.factorisations() == 1);
    } else {
      CHECK(cholmod.last_path() == CholmodSolver::Path::Factorised);
      CHECK(cholmod.factorisations() == 2);
    }
    const Eigen::VectorXd reference = Eigen::LDLT<Eigen::MatrixXd>(k).solve(modified.rhs);
    CHECK((*x - reference).norm() <= 1e-8 * reference.norm());
  }
}

TEST_CASE("the lower triangle written straight into compressed columns is the dense one's",
          "[solver]") {
  // BlockSystem::lower_triangle fills CHOLMOD's compressed columns directly (no triplets):
  // against the plain dense matrix's lower triangle, entry for entry, with couplings given
  // out of order, several couplings of one block pair (summed), and rigid rows (3 unknowns).
  // The same additions in the same order: equal to the last bit except where two couplings
  // of a pair are summed, where the order may differ (1e-15 relative).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (bool with_rigid : {false, true}) {
    std::vector<bool> rigid(9, false);
    if (with_rigid) rigid[2] = rigid[5] = rigid[8] = true;
    BlockSystem s;
    s.reset(rigid);
    for (Mat6& d : s.diagonal) {
      const Mat6 m = Mat6::NullaryExpr([&] { return u(rng); });
      d = m * m.transpose() + 6.0 * Mat6::Identity();
    }
    for (const auto& [row, col] : std::vector<std::pair<int, int>>{
             {4, 1}, {2, 0}, {8, 3}, {4, 1}, {3, 0}, {7, 2}, {5, 4}, {8, 7}, {1, 0}, {3, 0}}) {
      s.couplings.push_back({row, col, Mat6::NullaryExpr([&] { return u(rng); })});
    }
    const Eigen::SparseMatrix<double> lower = s.lower_triangle();
    INFO("rigid rows: " << with_rigid);
    CHECK(lower.isCompressed());
    CHECK(lower.rows() == s.unknowns());
    const Eigen::MatrixXd reference = s.dense().triangularView<Eigen::Lower>();
    CHECK((Eigen::MatrixXd(lower) - reference).cwiseAbs().maxCoeff() <= 1e-15 * reference.cwiseAbs().maxCoeff());
    // Rows sorted within each column, as CHOLMOD requires of a matrix marked sorted.
    bool sorted = true;
    for (int j = 0; j < lower.outerSize(); ++j) {
      for (int k = lower.outerIndexPtr()[j] + 1; k < lower.outerIndexPtr()[j + 1]; ++k) {
        sorted = sorted && lower.innerIndexPtr()[k - 1] < lower.innerIndexPtr()[k];
      }
    }
    CHECK(sorted);
  }
}

TEST_CASE("the analysis is kept on a pattern that survives contact changes", "[solver]") {
  // A system whose couplings all lie in the analysed pattern (a contact
  // gone) is factorised on that analysis, with explicit zeros; a new coupling makes a new
  // analysis, of the union, so the system without it is then factorised without another.
  // Every answer agrees with dense LDLT of its own system to 1e-10 relative (the bound of the
  // first test: two backward-stable factorisations of one SPD matrix).
  const BlockSystem all = settling_wall_system(100, 3);
  REQUIRE(all.couplings.size() > 10);
  BlockSystem fewer = all;  // two contacts gone
  fewer.couplings.erase(fewer.couplings.begin() + 3);
  fewer.couplings.erase(fewer.couplings.begin() + 7);
  BlockSystem more = fewer;  // a coupling no contact of `all` made: between rows 0 and last
  const int last = more.block_rows() - 1;
  bool coupled = false;
  for (const BlockSystem::Coupling& c : all.couplings) coupled |= (c.row == last && c.col == 0);
  REQUIRE_FALSE(coupled);
  more.couplings.push_back({last, 0, 1e3 * Mat6::Identity()});

  SparseCholesky factor;
  auto solves_like_dense = [&factor](const BlockSystem& s) {
    Eigen::SparseMatrix<double> lower = s.lower_triangle();
    lower.makeCompressed();
    REQUIRE(factor.factorize(lower));
    const Eigen::VectorXd reference = *solve_dense(s);
    CHECK((factor.solve(s.rhs) - reference).norm() <= 1e-10 * reference.norm());
  };
  solves_like_dense(all);
  CHECK(factor.analyses() == 1);
  solves_like_dense(fewer);  // inside the analysed pattern
  CHECK(factor.analyses() == 1);
  solves_like_dense(all);
  CHECK(factor.analyses() == 1);
  solves_like_dense(more);  // a new entry: analysed again, on the union
  CHECK(factor.analyses() == 2);
  solves_like_dense(all);  // inside the union
  solves_like_dense(fewer);
  CHECK(factor.analyses() == 2);

  // Far more entries in the pattern than in the matrix: the next analysis drops them. A
  // system of the diagonal blocks alone plus the new coupling needs a new analysis (the
  // coupling (last, 0) is in the union, but take one outside it too), and the union would
  // have ~6 times its entries, far past kPatternSlack: it is analysed on its own pattern,
  // after which `all` needs an analysis again.
  BlockSystem bare = all;
  bare.couplings = {{last, 1, 1e3 * Mat6::Identity()}};
  solves_like_dense(bare);
  CHECK(factor.analyses() == 3);
  solves_like_dense(all);
  CHECK(factor.analyses() == 4);
}

TEST_CASE("a kept factor is refreshed when a CG costs more than the average solve since",
          "[solver]") {
  // The refresh rule (linear_solver.hpp): the system it was made for, solved again and
  // again, takes CG one iteration each (F = K), which never costs more than the average
  // (which carries the factorisation): no refactorisation in 30 solves. A drifted system
  // then takes several iterations, more than the average by then: the solve after it
  // factorises. Answers within 1e-8 of dense LDLT, as in the CG test above.
  const BlockSystem sys = settling_wall_system(100, 3);
  CholmodSolver cholmod;
  REQUIRE(cholmod.solve(sys));
  for (int k = 0; k < 30; ++k) REQUIRE(cholmod.solve_reusing(sys));
  CHECK(cholmod.stats().factorisations == 1);
  CHECK(cholmod.stats().cg_iterations <= 30);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  BlockSystem drifted = sys;
  for (Mat6& d : drifted.diagonal) d *= 1.0 + u(rng);
  const long before = cholmod.stats().cg_iterations;
  const auto x = cholmod.solve_reusing(drifted);
  REQUIRE(x);
  CHECK(cholmod.stats().factorisations == 1);
  CHECK(cholmod.stats().cg_iterations - before >= 3);  // a drift of 1e-3: several
  const Eigen::VectorXd reference = *solve_dense(drifted);
  CHECK((*x - reference).norm() <= 1e-8 * reference.norm());
  REQUIRE(cholmod.solve_reusing(drifted));
  CHECK(cholmod.stats().factorisations == 2);
  CHECK(cholmod.last_path() == CholmodSolver::Path::Factorised);
}

namespace {

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

}  // namespace

TEST_CASE("a factor rebuilt from its record is the factor recorded, bit for bit", "[solver][checkpoint]") {
  // The supernodal factor of a 400-brick wall's system, updated by two springs and downdated
  // by one (which turns it into a simplicial LDL'), recorded and rebuilt on a new object:
  // the same answers to the last bit, the same cost model (which decides the later paths),
  // and the same answer again after both refactorise a changed matrix on the kept analysis.
  const BlockSystem sys = settling_wall_system(400, 3);
  Eigen::SparseMatrix<double> lower = sys.lower_triangle();
  lower.makeCompressed();
  SparseCholesky factor;
  REQUIRE(factor.factorize(lower));
  REQUIRE(factor.supernodal());
  RankOneTerm a, b;
  a.entries = {{6 * 3 + 0, 3e4}, {6 * 4 + 1, -3e4}};
  b.entries = {{6 * 10 + 1, 2e4}, {6 * 11 + 2, 1e4}, {6 * 11 + 0, -2e4}};
  REQUIRE(factor.modify({a, b}, true));
  REQUIRE(factor.modify({a}, false));
  const FactorRecord record = factor.record();
  CHECK(record.modifications.size() == 2);
  SparseCholesky rebuilt;
  REQUIRE(rebuilt.restore(record));
  CHECK(same_bits(rebuilt.solve(sys.rhs), factor.solve(sys.rhs)));
  CHECK(rebuilt.refactorisation_cost() == factor.refactorisation_cost());
  CHECK(rebuilt.modification_cost({a, b}) == factor.modification_cost({a, b}));
  CHECK(rebuilt.analyses() == factor.analyses());
  Eigen::SparseMatrix<double> changed = lower * 1.0001;
  changed.makeCompressed();
  REQUIRE(factor.factorize(changed));
  REQUIRE(rebuilt.factorize(changed));
  CHECK(same_bits(rebuilt.solve(sys.rhs), factor.solve(sys.rhs)));
  CHECK(rebuilt.analyses() == factor.analyses());  // the kept analysis served both
  // A record that does not hold together is refused, not half used.
  FactorRecord damaged = record;
  damaged.values.pop_back();
  SparseCholesky refused;
  CHECK_FALSE(refused.restore(damaged));
  CHECK_FALSE(refused.has_factor());
}

TEST_CASE("a settling wall continued from its recorded workspace takes the unbroken run's steps",
          "[solver][checkpoint]") {
  // The 100-brick wall settling for 120 steps with the default solver path (a kept factor,
  // rank-one updates, CG on top): stopped at step k, its workspace recorded and put into a
  // new one, and the world (a copy) stepped on. Every block ends where the unbroken run's
  // does to the last bit, and the solver took the same paths (its counts agree). Without the
  // record the continued run factorises afresh and differs at round-off: the control below
  // shows the comparison can fail.
  const Scene scene = bench::brick_wall_scene(100, elastic_material("rock", 2700.0, 1e9, 0.25));
  constexpr int kSteps = 120;
  World whole = make_world(scene);
  StepWorkspace whole_ws;
  RunStats whole_stats;
  for (int k = 0; k < kSteps; ++k) REQUIRE(advance_step(whole, whole_ws, whole_stats).ok);
  const LinearSolveStats& s = whole_ws.solver.stats();
  REQUIRE(s.modifications > 0);  // the paths a record must carry were taken
  REQUIRE(s.reused > s.factorisations);
  const auto same_blocks = [](const World& a, const World& b) {
    for (std::size_t i = 0; i < a.blocks.size(); ++i) {
      for (std::size_t v = 0; v < a.blocks[i].vertices.size(); ++v) {
        const Vec2 p = a.blocks[i].vertices[v], q = b.blocks[i].vertices[v];
        if (std::memcmp(&p, &q, sizeof p) != 0) return false;
      }
      if (std::memcmp(&a.blocks[i].velocity, &b.blocks[i].velocity, sizeof(Vec3)) != 0) return false;
    }
    return true;
  };
  for (const int stop : {1, 37, 90}) {
    INFO("stopped at step " << stop);
    World first = make_world(scene);
    StepWorkspace first_ws;
    RunStats stats;
    for (int k = 0; k < stop; ++k) REQUIRE(advance_step(first, first_ws, stats).ok);
    const WorkspaceRecord record = record_workspace(first_ws);
    World continued = first;
    StepWorkspace continued_ws;
    REQUIRE(restore_workspace(continued_ws, record));
    RunStats continued_stats = stats;
    for (int k = stop; k < kSteps; ++k) REQUIRE(advance_step(continued, continued_ws, continued_stats).ok);
    CHECK(same_blocks(continued, whole));
    CHECK(continued_stats.open_close_total == whole_stats.open_close_total);
    const LinearSolveStats& c = continued_ws.solver.stats();
    CHECK(c.factorisations == s.factorisations);
    CHECK(c.modifications == s.modifications);
    CHECK(c.cg_iterations == s.cg_iterations);
    if (stop == 37) {
      World fresh = first;
      StepWorkspace fresh_ws;
      RunStats fresh_stats = stats;
      for (int k = stop; k < kSteps; ++k) REQUIRE(advance_step(fresh, fresh_ws, fresh_stats).ok);
      CHECK_FALSE(same_blocks(fresh, whole));
    }
  }
}
