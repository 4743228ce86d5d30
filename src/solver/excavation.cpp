#include "solver/excavation.hpp"

#include <algorithm>

#include "solver/energy.hpp"
#include "solver/world.hpp"

namespace dda {

int excavate_blocks(World& world, std::vector<Contact>& contacts, const std::vector<int>& indices) {
  // The scene's energy as it stands, springs included: what the removal changes is what it
  // takes away.
  const auto held = [&world, &contacts] {
    return scene_energy(world).total() - world.energy.contact_energy +
           contact_energy(world, contacts, world.penalty);
  };
  const double before = held();
  int removed = 0;
  for (const int i : indices) {
    Block& b = world.blocks[static_cast<std::size_t>(i)];
    if (b.excavated) continue;
    b.excavated = true;
    b.fixed = true;
    b.plastic = false;
    b.velocity.setZero();
    ++removed;
  }
  if (removed == 0) return 0;
  contacts.erase(std::remove_if(contacts.begin(), contacts.end(),
                                [&world](const Contact& c) {
                                  return world.blocks[static_cast<std::size_t>(c.key.vertex_block)].excavated ||
                                         world.blocks[static_cast<std::size_t>(c.key.edge_block)].excavated;
                                }),
                 contacts.end());
  for (std::size_t i = 0; i < world.bolts.size(); ++i) {
    Bolt& bolt = world.bolts[i];
    const bool cut = world.blocks[static_cast<std::size_t>(world.bolt_ends[2 * i].block)].excavated ||
                     world.blocks[static_cast<std::size_t>(world.bolt_ends[2 * i + 1].block)].excavated;
    if (cut && !bolt.broken) {
      bolt.broken = true;
      bolt.force = 0.0;
      bolt.broken_at = world.time;
    }
  }
  // The free blocks' unknowns, numbered again in block order (make_world's numbering).
  world.dof_count = 0;
  for (Block& b : world.blocks) {
    b.first_dof = b.fixed ? -1 : world.dof_count;
    if (!b.fixed) world.dof_count += 6;
  }
  world.energy.contact_energy = contact_energy(world, contacts, world.penalty);
  world.energy.excavation += before - held();
  return removed;
}

bool world_excavates(const World& world) {
  return std::any_of(world.stages.stages.begin(), world.stages.stages.end(),
                     [](const StageSpec& s) { return !s.excavate.empty(); });
}

}  // namespace dda
