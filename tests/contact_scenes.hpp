// Scenes with contacts for physics tests, built as plain structs.
#pragma once

#include <cmath>

#include "scene_builders.hpp"

namespace dda::test {

// A fixed triangular slope whose top face is the line through the origin at `slope_deg`,
// and a free b x h block standing on that face, centred at the origin.
inline Scene block_on_incline(double slope_deg, double friction_deg, double b, double h,
                              double dt, double end_time) {
  const double a = slope_deg * M_PI / 180.0;
  const Vec2 t(std::cos(a), std::sin(a));
  const Vec2 n(-std::sin(a), std::cos(a));
  const double big = 20.0;
  Scene s = base_scene(0, dt);
  s.control.steps.reset();
  s.control.end_time = end_time;
  s.control.max_displacement_ratio = 0.01;
  s.joint_materials[0].friction_angle = friction_deg;
  BlockSpec slope = block({-big * t, Vec2(big * t.x(), -big * t.y()), big * t});
  slope.fixed = true;
  s.blocks.push_back(slope);
  const Vec2 p1 = -0.5 * b * t, p2 = 0.5 * b * t;
  s.blocks.push_back(block({p1, p2, p2 + h * n, p1 + h * n}));
  return s;
}

}  // namespace dda::test
