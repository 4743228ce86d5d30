#include "solver/rotation/secant_column.hpp"

#include <utility>

#include "kinematics/block_matrices.hpp"
#include "solver/assembly.hpp"
#include "solver/rotation/rotation_columns.hpp"
#include "solver/rotation/secant_angles.hpp"

namespace dda {
namespace {

// settle_free_secants' rounds before it gives the blocks back to the global loop.
constexpr int kLocalSecantRounds = 10;

}  // namespace

void SecantColumn::start_step(const World& world, const StepContext& /*ctx*/, LoopTerms& terms,
                              RotationIterate& it) const {
  it.angles = last_rotation_increments(world);
  set_rotation_columns(world, it.angles, secant_rotation_column, terms);
}

// Block i's spin at the mean rates of its increments db over the step: r0 / dt and the
// block-frame strain increment / dt (the increment turned by the mid-step angle, as the
// update will take it).
Spin SecantColumn::mean_spin(const World& world, const StepContext& ctx, std::size_t i,
                             const Vec6& db) const {
  const Block& b = world.blocks[i];
  const Mat2 column = solved_rotation_column(&ctx, static_cast<int>(i), db[kR0]);
  // finite_rotation_polar: D's mean over the step, the increment turned by the mid-step
  // angle (spatial_rotating_inertia_force reads D, not the Hencky strain's rate).
  const Vec3 increment = moves_present_shape(b) ? dda::block_frame_increment(b, db)
                                                : block_frame_increment(b, db, &column);
  return Spin{db[kR0] / ctx.dt, increment / ctx.dt};
}

// The spins moved to the answer's mean rates. Returns how many plastic blocks' spins moved
// by more than their `tolerance` (secant_tolerances; spin_error): their inertia was not that
// of the answer, which must be solved again. (A plastic block's Newton converged at its
// second solve, assembled with the first iterate's spins, whose strain rate was 3.2 1/s
// against the answer's 4.4: the first iterate is the material's elastic prediction, far from
// a flow at zero stiffness. With the D^2 term so short, a Mohr-Coulomb block stretching at
// its tension cut-off in flight gained 6.5 J/m a step.) Elastic blocks are not checked:
// their iterates differ by the contacts' modes only, and checking them too cost box150 a
// tenth more solves (7220 against 6539) for rattling rock blocks whose stiffness, not their
// inertia, sets their strain. Without `tolerance`, 0.
int SecantColumn::follow_spins(const World& world, const Eigen::VectorXd& d,
                               const StepContext& ctx, LoopTerms& terms,
                               const std::vector<double>* tolerance) const {
  int moved = 0;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed || b.rigid) continue;
    const Spin now = mean_spin(world, ctx, i, d.segment<6>(b.first_dof));
    if (tolerance != nullptr && b.plastic &&
        spin_error(b, terms.spins[i], now, ctx.dt) > (*tolerance)[i]) {
      ++moved;
    }
    terms.spins[i] = now;
  }
  return moved;
}

// follow_spins after a solve, in both contact loops: its check (at secant_tolerances, built
// only then) when `check`, i.e. when the scene has plastic blocks and the block terms hold
// spins followed from an iterate; otherwise the spins follow unchecked.
int SecantColumn::follow_answer_spins(const World& world, const Eigen::VectorXd& d,
                                      const StepContext& ctx, LoopTerms& terms,
                                      bool check) const {
  if (!check) return follow_spins(world, d, ctx, terms);
  const std::vector<double> tolerance = secant_tolerances(world, world.contacts);
  return follow_spins(world, d, ctx, terms, &tolerance);
}

// Once the contacts agree (the converged solver): when every block whose secant angle is off
// (`off`, from follow_secant_angles) touches nothing (its contacts all open, which add no
// terms), its rows of the step's system are its own block terms alone, so its increments are
// solved block by block (6 x 6, or 3 x 3 for a rigid block) until its angle agrees, with no
// global solve (a third of the solves of the hopper's first 1.5 s were for tumbling blocks in
// flight). The other blocks keep the angles they were solved with. On success `angles`,
// the loop's T, the spins and `block_terms` are those of the increments in d. False when an off
// block touches another (nothing changed), or after kLocalSecantRounds rounds: `angles` and
// d are as they came, but the loop's T, the spins and `block_terms` are the last round's, for the
// caller to set from its angles as it does after any secant change.
bool SecantColumn::settle_free_secants(const World& world, const std::vector<int>& off,
                                       bool spinning, std::vector<double>& angles,
                                       const StepContext& ctx, LoopTerms& terms,
                                       BlockSystem& block_terms, Eigen::VectorXd& d) const {
  std::vector<unsigned char> touching(world.blocks.size(), 0);
  for (const Contact& c : world.contacts) {
    if (c.state.mode == ContactMode::Open) continue;
    touching[static_cast<std::size_t>(c.key.vertex_block)] = 1;
    touching[static_cast<std::size_t>(c.key.edge_block)] = 1;
  }
  for (const int i : off) {
    if (touching[static_cast<std::size_t>(i)] != 0) return false;
  }
  std::vector<double> local = angles;  // the off blocks' from the r0 just solved
  for (const int i : off) {
    local[static_cast<std::size_t>(i)] = d[world.blocks[static_cast<std::size_t>(i)].first_dof + kR0];
  }
  Eigen::VectorXd x = d;
  for (int round = 0; round < kLocalSecantRounds; ++round) {
    set_rotation_columns(world, local, secant_rotation_column, terms);
    if (spinning) follow_spins(world, x, ctx, terms);
    assemble(world, ctx, block_terms);  // reads `terms` through ctx.loop
    bool agrees = true;
    std::vector<double> next = local;
    for (const int i : off) {
      const Block& b = world.blocks[static_cast<std::size_t>(i)];
      const int n = b.rigid ? BlockSystem::kRigidUnknowns : 6;
      const int row = block_row(b);
      const Mat6& k = block_terms.diagonal[static_cast<std::size_t>(row)];
      Vec6 xb = Vec6::Zero();
      xb.head(n) = k.topLeftCorner(n, n).ldlt().solve(block_terms.rhs.segment(b.first_dof, n));
      x.segment<6>(b.first_dof) = xb;
      if (free_secant_off(world, b, xb[kR0], local[static_cast<std::size_t>(i)])) agrees = false;
      // Its spins too, at the free blocks' tolerance (follow_spins holds plastic blocks to
      // theirs by global solves; here it costs 6 x 6 solves only).
      if (spinning && !b.rigid &&
          spin_error(b, terms.spins[static_cast<std::size_t>(i)],
                     mean_spin(world, ctx, static_cast<std::size_t>(i), xb),
                     ctx.dt) > kSecantDisplacementShare * world.w0) {
        agrees = false;
      }
      next[static_cast<std::size_t>(i)] = xb[kR0];
    }
    if (agrees) {
      // T, spins and block terms are those the increments were solved with.
      angles = local;
      d = x;
      return true;
    }
    local = next;
  }
  return false;
}

// The contact loop's outer fixed point: the secant angles follow the answer's r0 (when the
// converged solver allows, blocks in flight settle block by block first), T follows the
// angles that moved, and, with the rotating inertia, the spins follow the answer's mean
// rates: a spin off them counts as a secant angle off, both being the step's own answer fed
// back into its equations.
Followed SecantColumn::follow_solve(const World& world, Eigen::VectorXd& d,
                                    const StepContext& ctx, LoopTerms& terms,
                                    RotationIterate& it, const SolveFollow& how) const {
  Followed f;
  std::vector<int> off;  // blocks whose secant angle is off (follow_secant_angles)
  std::vector<double> solved_angles;
  if (how.free_block_terms != nullptr) solved_angles = it.angles;
  f.moved = follow_secant_angles(world, world.contacts, d, it.angles,
                                 how.free_block_terms != nullptr ? &off : nullptr);
  if (f.moved > 0 && how.free_block_terms != nullptr &&
      settle_free_secants(world, off, how.spinning, solved_angles, ctx, terms,
                          *how.free_block_terms, d)) {
    // Blocks in flight settled block by block: the contacts are then to see the new
    // increments and T.
    it.angles = std::move(solved_angles);
    f.moved = 0;
    f.settled_free_blocks = true;
  }
  if (f.moved > 0) {
    set_rotation_columns(world, it.angles, secant_rotation_column, terms);
    f.columns_changed = true;
  }
  if (how.spinning) f.moved += follow_answer_spins(world, d, ctx, terms, how.check_spins);
  return f;
}

}  // namespace dda
