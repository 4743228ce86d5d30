#include "solver/rotation/rotation_columns.hpp"

#include "kinematics/block_matrices.hpp"

namespace dda {

std::vector<double> last_rotation_increments(const World& world) {
  std::vector<double> angles(world.blocks.size(), 0.0);
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    angles[i] = world.blocks[i].last_rotation_increment;
  }
  return angles;
}

void set_rotation_columns(const World& world, const std::vector<double>& angles,
                          Mat2 (*column)(double), LoopTerms& terms) {
  terms.block_ts.assign(world.blocks.size(), shi_t());
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    if (world.blocks[i].fixed) continue;
    terms.block_ts[i] = t_with_rotation_column(column(angles[i]));
  }
}

Mat2 solved_rotation_column(const StepContext* ctx, int index, double r0) {
  if (ctx == nullptr) return secant_rotation_column(r0);
  return rotation_column(step_t(*ctx, index));
}

}  // namespace dda
