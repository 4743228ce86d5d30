// The packed brick wall of the contact benchmarks: N bricks 1 m x 0.5 m in offset rows on a
// fixed base, under gravity, Mohr-Coulomb joints at 30 degrees, dt 0.002 s, all of one
// material (given). Used by BM_PackedWall and BM_PlasticWall.
#pragma once

#include <cmath>

#include "solver/scene.hpp"

namespace dda::bench {

inline Scene brick_wall_scene(int n, const Material& material) {
  Scene s;
  s.materials.push_back(material);
  s.joint_materials[0] = JointMaterial{"default", 30.0, 0.0, 0.0};
  s.control.time_steps = {0.002};
  s.control.steps = 1 << 30;
  // A settling wall keeps ~7 open-close iterations a step (side contacts near the friction
  // limit); Shi's limit of 8 would cut steps now and then, which measures the cuts, not a step.
  s.control.max_open_close = 30;
  const int cols = static_cast<int>(std::ceil(std::sqrt(2.0 * n)));  // about square in metres
  // The same control in metres at every size: a step may move a vertex 1 cm (2 % of a
  // brick's height), so the search distance (2.5 x ratio x w0) is 2.5 cm. A fixed ratio
  // would let w0 = half the wall's width scale it: at 10000 bricks 0.01 w0 is 0.7 m, more
  // than a brick, and detection would pair every brick with its neighbours' neighbours.
  const double w0 = 0.5 * (cols + 2.0);  // the base is the widest thing in the scene
  s.control.max_displacement_ratio = 0.01 / w0;
  BlockSpec base;
  base.vertices = {{-1.0, -1.0}, {cols + 1.0, -1.0}, {cols + 1.0, 0.0}, {-1.0, 0.0}};
  base.fixed = true;
  s.blocks.push_back(base);
  for (int i = 0; i < n; ++i) {
    const int r = i / cols, c = i % cols;
    const double x = c + (r % 2 ? 0.5 : 0.0), y = 0.5 * r;
    BlockSpec b;
    b.vertices = {{x, y}, {x + 1.0, y}, {x + 1.0, y + 0.5}, {x, y + 0.5}};
    s.blocks.push_back(b);
  }
  return s;
}

}  // namespace dda::bench
