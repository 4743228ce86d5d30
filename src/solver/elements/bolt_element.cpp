#include "solver/elements/bolt_element.hpp"

#include <cmath>

#include "kinematics/block_matrices.hpp"

namespace dda {
namespace {

// The gradient of a bolt's extension: dl = on_a . d_a + on_b . d_b over its ends' blocks'
// increments (a fixed block's part is never read). Null when its ends coincide (no axis).
struct BoltGradient {
  bool defined = false;
  Vec6 on_a = Vec6::Zero();
  Vec6 on_b = Vec6::Zero();
};

BoltGradient bolt_gradient(const World& world, const StepContext& ctx, std::size_t i) {
  BoltGradient g;
  const BoltEnd& a = world.bolt_ends[2 * i];
  const BoltEnd& b = world.bolt_ends[2 * i + 1];
  const Vec2 axis = b.current - a.current;
  const double length = axis.norm();
  if (!(length > 0.0)) return g;
  const Vec2 e = axis / length;
  const Block& block_a = world.blocks[static_cast<std::size_t>(a.block)];
  const Block& block_b = world.blocks[static_cast<std::size_t>(b.block)];
  g.on_a = -(step_t(ctx, a.block).at(a.current - block_a.moments.centroid).transpose() * e);
  g.on_b = step_t(ctx, b.block).at(b.current - block_b.moments.centroid).transpose() * e;
  g.defined = true;
  return g;
}

double extension_of(const World& world, std::size_t i, const BoltGradient& g,
                    const Eigen::VectorXd& d) {
  const Block& a = world.blocks[static_cast<std::size_t>(world.bolt_ends[2 * i].block)];
  const Block& b = world.blocks[static_cast<std::size_t>(world.bolt_ends[2 * i + 1].block)];
  double dl = 0.0;
  if (!a.fixed) dl += g.on_a.dot(d.segment<6>(a.first_dof));
  if (!b.fixed) dl += g.on_b.dot(d.segment<6>(b.first_dof));
  return dl;
}

// The mode bolt i is solved in: the loop's, or (outside a loop) the one its force starts in.
BoltMode mode_of(const World& world, const StepContext& ctx, std::size_t i) {
  if (ctx.loop != nullptr && !ctx.loop->bolt_modes.empty()) return ctx.loop->bolt_modes[i];
  return start_bolt_mode(world.bolts[i].law, world.bolts[i].force);
}

void assemble_bolts(const World& world, const StepContext& ctx, BlockSystem& system) {
  for (std::size_t i = 0; i < world.bolts.size(); ++i) {
    const Bolt& bolt = world.bolts[i];
    if (bolt.broken) continue;
    const BoltGradient g = bolt_gradient(world, ctx, i);
    if (!g.defined) continue;
    const BoltMode mode = mode_of(world, ctx, i);
    // The force the energy's linear term stands for: N0 while elastic, +-N_y while yielding.
    const double n = mode == BoltMode::Elastic ? bolt.force : bolt_force(bolt.law, mode, bolt.force, 0.0);
    const double k = mode == BoltMode::Elastic ? bolt.law.stiffness : 0.0;
    const Block& a = world.blocks[static_cast<std::size_t>(world.bolt_ends[2 * i].block)];
    const Block& b = world.blocks[static_cast<std::size_t>(world.bolt_ends[2 * i + 1].block)];
    if (!a.fixed) {
      system.diagonal[static_cast<std::size_t>(block_row(a))] += k * g.on_a * g.on_a.transpose();
      system.rhs.segment<6>(a.first_dof) -= n * g.on_a;
    }
    if (!b.fixed) {
      system.diagonal[static_cast<std::size_t>(block_row(b))] += k * g.on_b * g.on_b.transpose();
      system.rhs.segment<6>(b.first_dof) -= n * g.on_b;
    }
    if (!a.fixed && !b.fixed && k > 0.0) {
      // Stored below the diagonal (BlockSystem::Coupling: row > col); the lower triangle and
      // the products add couplings of the same pair, so a contact's may stand beside it.
      const int row_a = block_row(a), row_b = block_row(b);
      if (row_a > row_b) {
        system.couplings.push_back({row_a, row_b, Mat6(k * g.on_a * g.on_b.transpose())});
      } else {
        system.couplings.push_back({row_b, row_a, Mat6(k * g.on_b * g.on_a.transpose())});
      }
    }
  }
}

// One step of bolt i as its mode and the increments d make it.
BoltStepWork step_of(const World& world, const StepContext& ctx, std::size_t i,
                     const Eigen::VectorXd& d) {
  const Bolt& bolt = world.bolts[i];
  const BoltGradient g = bolt_gradient(world, ctx, i);
  const double dl = g.defined ? extension_of(world, i, g, d) : 0.0;
  return bolt_step_work(bolt.law, mode_of(world, ctx, i), bolt.force, dl);
}

bool breaks(const Bolt& bolt, const BoltStepWork& w) {
  return bolt.plastic_extension + std::abs(w.plastic_extension) > bolt.rupture_extension;
}

// The step's loss to the integration, the plastic work, and the spring energy a bar that
// breaks in the step lets go (it leaves the account's stored energy with nothing to do work:
// the rupture's own loss).
void book_bolts(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                StepEnergy& s) {
  for (std::size_t i = 0; i < world.bolts.size(); ++i) {
    const Bolt& bolt = world.bolts[i];
    if (bolt.broken) continue;
    const BoltStepWork w = step_of(world, ctx, i, d);
    s.damping_dissipation += w.integration_loss;
    s.plastic_work += w.plastic_work;
    if (breaks(bolt, w)) s.plastic_work += bolt_stored_energy(bolt.law, w.end_force);
  }
}

void add_bolt_energy(const World& world, double /*penalty*/, double& e) {
  for (const Bolt& bolt : world.bolts) {
    if (!bolt.broken) e += bolt_stored_energy(bolt.law, bolt.force);
  }
}

void start_bolt_modes(const World& world, LoopTerms& terms) {
  if (world.bolts.empty()) return;
  terms.bolt_modes.resize(world.bolts.size());
  for (std::size_t i = 0; i < world.bolts.size(); ++i) {
    terms.bolt_modes[i] = start_bolt_mode(world.bolts[i].law, world.bolts[i].force);
  }
}

int follow_bolt_modes(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                      LoopTerms& terms) {
  int changed = 0;
  for (std::size_t i = 0; i < world.bolts.size(); ++i) {
    const Bolt& bolt = world.bolts[i];
    if (bolt.broken) continue;
    const BoltGradient g = bolt_gradient(world, ctx, i);
    if (!g.defined) continue;
    const BoltMode next =
        follow_bolt_mode(bolt.law, terms.bolt_modes[i], bolt.force, extension_of(world, i, g, d));
    if (next != terms.bolt_modes[i]) {
      terms.bolt_modes[i] = next;
      ++changed;
    }
  }
  return changed;
}

void commit_bolts(World& world, const Eigen::VectorXd& d, const StepContext& ctx) {
  for (std::size_t i = 0; i < world.bolts.size(); ++i) {
    Bolt& bolt = world.bolts[i];
    if (bolt.broken) continue;
    const BoltStepWork w = step_of(world, ctx, i, d);
    const bool broke = breaks(bolt, w);
    bolt.plastic_extension += std::abs(w.plastic_extension);
    bolt.force = w.end_force;
    if (broke) {
      bolt.broken = true;
      bolt.force = 0.0;
      bolt.broken_at = world.time + ctx.dt;
    }
  }
}

}  // namespace

const ForceElement kBoltElement{assemble_bolts,   book_bolts,        add_bolt_energy,
                                start_bolt_modes, follow_bolt_modes, commit_bolts};

}  // namespace dda
