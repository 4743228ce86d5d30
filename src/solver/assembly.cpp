#include "solver/assembly.hpp"

#include "kinematics/block_matrices.hpp"
#include "kinematics/rotating_inertia.hpp"
#include "solver/configuration_update.hpp"

namespace dda {
namespace {

void add_block_terms(const World& world, int index, const StepContext& ctx, Mat6& k,
                     Eigen::Ref<Vec6> f) {
  const Block& b = world.blocks[static_cast<std::size_t>(index)];
  const LinearT& t = step_t(ctx, index);
  const double density = density_now(world, b);
  const Mat6 mass = mass_matrix(t, b.moments, density);
  const Vec6 v0 = ctx.dynamic_coefficient * b.velocity;
  k += (2.0 / (ctx.dt * ctx.dt)) * mass;
  // In the ground's frame under base shaking, gravity less the ground's acceleration.
  f += body_force(t, b.moments, density, world.gravity - ctx.base_acceleration) +
       (2.0 / ctx.dt) * (mass * v0);
  // The quadratic velocity terms of a deformable block's inertia in its rotating frame
  // (centripetal, Coriolis; kinematics/rotating_inertia.hpp), taken to the right-hand side.
  // Turned to the global frame at the step's start, where the step also holds the block's
  // stress (initial_stress_force below): a steady spin then balances with no shear in the
  // block frame (at the mid-step angle, half a step's turn, r0/2, would show as shear).
  if (!ctx.spins.empty() && !b.rigid) {
    const RotationUpdate treatment = world.control.rotation_update;
    const Spin& spin = ctx.spins[static_cast<std::size_t>(index)];
    f -= spatial_increments(treatment, b)
             ? spatial_rotating_inertia_force(b.material_inertia, b.rotation,
                                              stretch_strain(treatment, b), spin)
             : rotating_inertia_force(b.material_inertia, b.rotation, b.local_strain, spin);
  }
  if (b.plastic && !ctx.material_terms.empty()) {
    // Newton: the stress at increment de is taken as s + D_t (de - de_k) (the material
    // linearised at the last solution, solver/material_coupling.hpp).
    const MaterialLinearization& l = ctx.material_terms[static_cast<std::size_t>(index)];
    const double area = stress_area(world.control.rotation_update, b);
    k.block<3, 3>(kEx, kEx) += area * l.tangent;
    f.segment<3>(kEx) -= area * (l.stress - l.tangent * l.strain_increment);
  } else if (!b.rigid) {
    // (The stress's area: stress_area, which only finite_rotation_polar changes.)
    Moments stressed = b.moments;
    stressed.area = stress_area(world.control.rotation_update, b);
    k += elastic_stiffness(stressed, elastic_of(world, b));
    f += initial_stress_force(stressed, b.stress);
  }
}

// A force (N per metre) at point `at` of block `index`, constant over the step: point loads
// and joint water. Fixed blocks take none.
void add_point_force(const World& world, const StepContext& ctx, int index, const Vec2& at,
                     const Vec2& force, BlockSystem& system) {
  const Block& b = world.blocks[static_cast<std::size_t>(index)];
  if (b.fixed) return;
  const Mat26 tp = step_t(ctx, index).at(at - b.moments.centroid);
  system.rhs.segment<6>(b.first_dof) += point_force(tp, force);
}

}  // namespace

std::vector<bool> rigid_rows(const World& world) {
  std::vector<bool> rigid(static_cast<std::size_t>(world.dof_count / 6), false);
  for (const Block& b : world.blocks) {
    if (!b.fixed) rigid[static_cast<std::size_t>(block_row(b))] = b.rigid;
  }
  return rigid;
}

void assemble(const World& world, const StepContext& ctx, BlockSystem& system) {
  system.reset(rigid_rows(world));
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed) continue;
    const int row = block_row(b);
    add_block_terms(world, static_cast<int>(i), ctx, system.diagonal[row],
                    system.rhs.segment<6>(b.first_dof));
  }
  for (const Pin& pin : world.pins) {
    const Block& b = world.blocks[pin.block];
    if (b.fixed) continue;  // a pin on a fixed block holds nothing that moves
    const Mat26 tp = step_t(ctx, pin.block).at(pin.current - b.moments.centroid);
    system.diagonal[block_row(b)] += spring_stiffness(tp, ctx.penalty);
    system.rhs.segment<6>(b.first_dof) += spring_force(tp, ctx.penalty, pin.anchor - pin.current);
  }
  for (const PointLoad& load : world.loads) {
    add_point_force(world, ctx, load.block, load.current, load.force, system);
  }
  for (const BlockForce& w : world.water_forces) {
    add_point_force(world, ctx, w.block, w.point, w.force, system);
  }
}

}  // namespace dda
