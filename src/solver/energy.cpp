#include "solver/energy.hpp"

namespace dda {

EnergyTotals scene_energy(const World& world) {
  EnergyTotals e;
  for (const Block& b : world.blocks) {
    if (b.fixed) continue;
    const double mass = b.density * b.moments.area;
    e.kinetic += kinetic_energy(b);
    e.potential -= mass * world.gravity.dot(b.moments.centroid);
    e.strain_energy += 0.5 * b.moments.area * b.strain.dot(b.elastic * b.strain);
  }
  return e;
}

}  // namespace dda
