// What both families of treatments use to move the material points that ride on blocks.
#pragma once

#include <Eigen/Dense>

#include "kinematics/types.hpp"
#include "solver/world.hpp"

namespace dda {

inline Vec6 increments_of(const Block& b, const Eigen::VectorXd& d) {
  return d.segment<6>(b.first_dof);
}

// The material points that ride on blocks (pins, point loads, monitors, bolt ends: each has `block`,
// `initial` and `current`): every one on a free block set to where(block, point).
template <class Where>
void move_carried_points(World& world, Where where) {
  const auto move = [&world, &where](auto& points) {
    for (auto& p : points) {
      const Block& b = world.blocks[static_cast<std::size_t>(p.block)];
      if (!b.fixed) p.current = where(b, p);
    }
  };
  move(world.pins);
  move(world.loads);
  move(world.monitors);
  move(world.bolt_ends);
}

}  // namespace dda
