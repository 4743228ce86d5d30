#include "solver/elements/point_force_element.hpp"

#include "kinematics/block_matrices.hpp"

namespace dda {
namespace {

// A force (N per metre) at point `at` of block `index`, constant over the step: point loads
// and joint water. Fixed blocks take none.
void add_point_force(const World& world, const StepContext& ctx, int index, const Vec2& at,
                     const Vec2& force, BlockSystem& system) {
  const Block& b = world.blocks[static_cast<std::size_t>(index)];
  if (b.fixed) return;
  const Mat26 tp = step_t(ctx, index).at(at - b.moments.centroid);
  system.rhs.segment<6>(b.first_dof) += point_force(tp, force);
}

void assemble_point_forces(const World& world, const StepContext& ctx, BlockSystem& system) {
  for (const PointLoad& load : world.loads) {
    add_point_force(world, ctx, load.block, load.current, load.force, system);
  }
  for (const BlockForce& w : ctx.water_forces) {
    add_point_force(world, ctx, w.block, w.point, w.force, system);
  }
}

// A constant force at a material point: its work on the point's motion.
double point_force_work(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                        int index, const Vec2& at, const Vec2& force) {
  const Block& b = world.blocks[static_cast<std::size_t>(index)];
  if (b.fixed) return 0.0;
  const Mat26 tp = step_t(ctx, index).at(at - b.moments.centroid);
  return force.dot(tp * d.segment<6>(b.first_dof));
}

void book_point_forces(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                       StepEnergy& s) {
  for (const PointLoad& load : world.loads) {
    s.load_work += point_force_work(world, d, ctx, load.block, load.current, load.force);
  }
  for (const BlockForce& w : ctx.water_forces) {
    s.load_work += point_force_work(world, d, ctx, w.block, w.point, w.force);
  }
}

}  // namespace

// Point loads and joint water.
const ForceElement kPointForceElement{assemble_point_forces, book_point_forces, nullptr,
                                      nullptr, nullptr, nullptr};

}  // namespace dda
