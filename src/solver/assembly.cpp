#include "solver/assembly.hpp"

#include "solver/force_element.hpp"

namespace dda {

std::vector<bool> rigid_rows(const World& world) {
  std::vector<bool> rigid(static_cast<std::size_t>(world.dof_count / 6), false);
  for (const Block& b : world.blocks) {
    if (!b.fixed) rigid[static_cast<std::size_t>(block_row(b))] = b.rigid;
  }
  return rigid;
}

void assemble(const World& world, const StepContext& ctx, BlockSystem& system) {
  system.reset(rigid_rows(world));
  for (const ForceElement& element : force_elements()) element.assemble(world, ctx, system);
}

}  // namespace dda
