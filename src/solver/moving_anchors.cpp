#include "solver/moving_anchors.hpp"

namespace dda {

void move_pin_anchors(World& world, const Vec2& per_step) {
  for (Pin& p : world.pins) {
    const double before = (p.current - p.anchor).squaredNorm();
    p.anchor += per_step;
    world.energy.load_work += 0.5 * world.penalty * ((p.current - p.anchor).squaredNorm() - before);
  }
}

std::function<void(World&)> moving_anchors(const Vec2& per_step) {
  return [per_step](World& world) { move_pin_anchors(world, per_step); };
}

}  // namespace dda
