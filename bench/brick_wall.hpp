// The packed brick wall of the contact benchmarks: N blocks in running bond on a fixed base,
// bricks 1 m x 0.5 m, the odd rows closed at both ends by half bricks (0.5 m x 0.5 m), rows
// filled from the bottom (the top row may be partial); under gravity, Mohr-Coulomb joints at
// 30 degrees, dt 0.002 s, all of one material (given). Used by BM_PackedWall and
// BM_PlasticWall. (Formerly the odd rows were full bricks shifted by half a brick:
// the end brick of every even row then stood with its centroid right above the corner of
// the brick below, and the wall's ends toppled slowly, so it never settled.)
#pragma once

#include <cmath>
#include <vector>

#include "solver/scene.hpp"

namespace dda::bench {

inline Scene brick_wall_scene(int n, const Material& material) {
  Scene s;
  s.materials.push_back(material);
  s.joint_materials[0] = JointMaterial{"default", 30.0, 0.0, 0.0};
  s.control.time_steps = {0.002};
  s.control.steps = 1 << 30;
  // While it settles, a wall takes up to ~15 open-close iterations in some steps; Shi's limit
  // of 8 would cut steps now and then, which measures the cuts, not a step.
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
  for (int row = 0, placed = 0; placed < n; ++row) {
    std::vector<double> joints;  // x of the vertical joints of this row, ends included
    if (row % 2 == 0) {
      for (int c = 0; c <= cols; ++c) joints.push_back(c);
    } else {
      joints.push_back(0.0);
      for (int c = 0; c < cols; ++c) joints.push_back(c + 0.5);
      joints.push_back(cols);
    }
    const double y = 0.5 * row;
    for (std::size_t k = 0; k + 1 < joints.size() && placed < n; ++k, ++placed) {
      const double x0 = joints[k], x1 = joints[k + 1];
      BlockSpec b;
      b.vertices = {{x0, y}, {x1, y}, {x1, y + 0.5}, {x0, y + 0.5}};
      s.blocks.push_back(b);
    }
  }
  return s;
}

}  // namespace dda::bench
