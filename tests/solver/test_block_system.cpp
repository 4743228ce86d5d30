// The reduced system of rigid blocks: BlockSystem's dof map, and the
// step's solve (solve_system) against the full six-slot system with the rigid blocks'
// strain increments constrained to zero, solved densely on its own.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "support/scene_builders.hpp"
#include "solver/assembly.hpp"
#include "solver/contact_assembly.hpp"
#include "solver/linear_solver.hpp"
#include "solver/run.hpp"
#include "solver/step_solve.hpp"
#include "solver/world.hpp"

using namespace dda;

namespace {

// Rigid and deformable squares stacked in two columns on a fixed floor, rigid on deformable
// and the other way round, touching their neighbours: after a few steps every kind of pair
// (rigid-rigid, rigid-deformable, deformable-deformable, each with the floor) has closed
// contacts.
World stacked_world() {
  Scene s = test::base_scene(20, 0.002);
  s.control.max_displacement_ratio = 0.01;
  s.joint_materials[0].friction_angle = 30.0;
  BlockSpec floor = test::block(test::rectangle(-1.0, -0.5, 3.0, 0.5));
  floor.fixed = true;
  s.blocks.push_back(floor);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 2; ++col) {
      BlockSpec b = test::block(test::rectangle(0.5 * col, 0.5 * row, 0.5, 0.5));
      b.rigid = (row + col) % 2 == 0;
      s.blocks.push_back(b);
    }
  }
  World w = make_world(s);
  const RunStats stats = run(w, [](const World&, const RunStats&) { return true; });
  REQUIRE_FALSE(stats.diverged);
  return w;
}

StepContext context(const World& w) {
  StepContext ctx;
  ctx.dt = 0.002;
  ctx.penalty = w.penalty;
  ctx.dynamic_coefficient = 1.0;
  return ctx;
}

// The reference: the whole six-slot matrix of the assembled blocks, written out here from
// the 6x6 blocks; the rigid blocks' strain slots (read from the world, not from the dof
// map) held at zero by dropping their rows and columns, the rest solved by a dense LDLT.
Eigen::VectorXd constrained_reference(const World& w, const BlockSystem& s) {
  const int n = 6 * s.block_rows();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (int b = 0; b < s.block_rows(); ++b) k.block<6, 6>(6 * b, 6 * b) = s.diagonal[b];
  for (const BlockSystem::Coupling& c : s.couplings) {
    k.block<6, 6>(6 * c.row, 6 * c.col) += c.k;
    k.block<6, 6>(6 * c.col, 6 * c.row) += c.k.transpose();
  }
  std::vector<int> kept;
  for (const Block& b : w.blocks) {
    if (b.fixed) continue;
    for (int i = 0; i < 6; ++i) {
      if (!b.rigid || i < 3) kept.push_back(b.first_dof + i);
    }
  }
  const int m = static_cast<int>(kept.size());
  Eigen::MatrixXd kk(m, m);
  Eigen::VectorXd f(m);
  for (int i = 0; i < m; ++i) {
    f[i] = s.rhs[kept[i]];
    for (int j = 0; j < m; ++j) kk(i, j) = k(kept[i], kept[j]);
  }
  const Eigen::VectorXd x = Eigen::LDLT<Eigen::MatrixXd>(kk).solve(f);
  Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < m; ++i) d[kept[i]] = x[i];
  return d;
}

// A rigid block's strain slots of d are exactly zero.
bool rigid_strains_zero(const World& w, const Eigen::VectorXd& d) {
  for (const Block& b : w.blocks) {
    if (b.fixed || !b.rigid) continue;
    if (d.segment<3>(b.first_dof + kEx) != Vec3::Zero()) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("rigid system: the dof map keeps a rigid row's u0, v0, r0", "[rigid][solver]") {
  BlockSystem s;
  s.reset(std::vector<bool>{false, true, true, false});
  CHECK(s.offset == std::vector<int>{0, 6, 9, 12, 18});
  CHECK(s.unknowns() == 18);
  CHECK(s.reduced());
  CHECK(s.reduced_index(6 + kR0) == 6 + 2);
  CHECK(s.reduced_index(6 + kEx) == -1);
  CHECK(s.reduced_index(18 + kGxy) == 12 + 5);
  Eigen::VectorXd slots = Eigen::VectorXd::LinSpaced(24, 1.0, 24.0);
  const Eigen::VectorXd unknowns = s.reduce(slots);
  REQUIRE(unknowns.size() == 18);
  CHECK(unknowns[6] == 7.0);    // block 1's u0
  CHECK(unknowns[9] == 13.0);   // block 2's u0
  CHECK(unknowns[12] == 19.0);  // block 3's u0
  // expand puts each unknown back in its slot and zeros in the rigid strain slots.
  for (int slot : {9, 10, 11, 15, 16, 17}) slots[slot] = 0.0;
  CHECK(s.expand(unknowns) == slots);
  s.reset(3);
  CHECK_FALSE(s.reduced());
}

TEST_CASE("rigid system: the reduced solve is the six-slot solve with rigid strains held at "
          "zero", "[rigid][solver]") {
  World w = stacked_world();
  const StepContext ctx = context(w);
  BlockSystem sys;
  assemble(w, ctx, sys);
  add_contact_terms(w, w.contacts, ctx, sys);
  REQUIRE(sys.unknowns() == 3 * 6 + 3 * 3);  // three deformable, three rigid blocks
  REQUIRE(sys.couplings.size() >= 5);
  const Eigen::VectorXd reference = constrained_reference(w, sys);

  // Both are backward-stable solutions of the same SPD system (condition ~1e8 with the
  // penalty springs): 1e-10 relative, as CHOLMOD against dense LDLT (test_linear_solver).
  SECTION("CHOLMOD, KLU and the dense LDLT through solve_system") {
    for (SolvePath path : {SolvePath::Factorise, SolvePath::Klu}) {
      StepWorkspace ws;
      ws.system = sys;
      const auto d = solve_system(ws, path);
      REQUIRE(d);
      CHECK((*d - reference).norm() <= 1e-10 * reference.norm());
      CHECK(rigid_strains_zero(w, *d));
    }
    BlockSystem reduced = sys;
    reduced.rhs = reduced.reduce(reduced.rhs);
    const auto dense = solve_dense(reduced);
    REQUIRE(dense);
    CHECK((reduced.expand(*dense) - reference).norm() <= 1e-10 * reference.norm());
    // The residual of the reduced system itself, by multiply (what CG on a kept factor iterates on).
    CHECK((multiply(reduced, *dense) - reduced.rhs).norm() <= 1e-9 * reduced.rhs.norm());
  }

  SECTION("CHOLMOD's factor updated by a contact of a rigid block") {
    // Factorise with one closed contact of a rigid and a deformable block held open, then
    // close it by a rank-one update with its springs (six-slot terms, reduced by
    // solve_system), as the open-close loop does.
    std::size_t chosen = w.contacts.size();
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
      const Contact& c = w.contacts[i];
      const Block& bv = w.blocks[static_cast<std::size_t>(c.key.vertex_block)];
      const Block& be = w.blocks[static_cast<std::size_t>(c.key.edge_block)];
      if (c.state.mode != ContactMode::Open && !bv.fixed && !be.fixed && bv.rigid != be.rigid) {
        chosen = i;
      }
    }
    REQUIRE(chosen < w.contacts.size());
    std::vector<Contact> opened = w.contacts;
    opened[chosen].state.mode = ContactMode::Open;
    // (solve_system's Modify path updates only when the cost model says so, which on so
    // small a system it does not: the factor is updated here directly, with the terms
    // reduced as solve_system reduces them.)
    BlockSystem before;
    assemble(w, ctx, before);
    add_contact_terms(w, opened, ctx, before);
    Eigen::SparseMatrix<double> lower = before.lower_triangle();
    lower.makeCompressed();
    SparseCholesky factor;
    REQUIRE(factor.factorize(lower));
    std::vector<RankOneTerm> springs;
    contact_spring_terms(w, w.contacts[chosen], ctx, springs);
    reduce_terms(sys, springs);
    REQUIRE(factor.modify(springs, true));
    const std::optional<Eigen::VectorXd> d = sys.expand(factor.solve(sys.reduce(sys.rhs)));
    // Update and solve are backward stable like a factorisation: 1e-10 as above.
    CHECK((*d - reference).norm() <= 1e-10 * reference.norm());
    CHECK(rigid_strains_zero(w, *d));
  }
}
