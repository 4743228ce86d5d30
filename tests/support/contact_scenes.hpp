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

// `count` free squares of 0.25 m dropped into a fixed box 1.5 m wide (floor and two walls,
// 0.2 m thick), five to a row, rows 0.35 m apart, the lowest 0.3 m above the floor; each
// turned by up to 5 degrees and shifted by up to 1 cm (fixed sequences, no random numbers),
// so they land on corners and tumble. As the hard-case box (verification/hard-cases): rock,
// friction 30 degrees, dt 0.002 s, displacement ratio 0.01. The rows fall, collide, pile up
// and come to rest within about 1 s (500 steps).
inline Scene blocks_into_box(int count) {
  Scene s = base_scene(0, 0.002);
  s.control.steps.reset();
  s.control.end_time = 10.0;
  s.control.max_displacement_ratio = 0.01;
  s.joint_materials[0].friction_angle = 30.0;
  const int rows = (count + 4) / 5;
  const double width = 1.5, height = 0.3 + 0.35 * rows + 0.3;
  const Polygon walls[] = {rectangle(-0.2, -0.2, width + 0.4, 0.2),
                           rectangle(-0.2, 0.0, 0.2, height), rectangle(width, 0.0, 0.2, height)};
  for (const Polygon& wall : walls) {
    BlockSpec b = block(wall);
    b.fixed = true;
    s.blocks.push_back(b);
  }
  for (int k = 0; k < count; ++k) {
    const double turn = 5.0 * M_PI / 180.0 * std::sin(1.7 * k + 0.3);
    const Vec2 centre(0.3 * (k % 5 + 0.5) + 0.01 * std::sin(2.3 * k + 1.0),
                      0.425 + 0.35 * (k / 5));
    // A square of circumradius 0.25 / sqrt 2, its first corner at -135 deg + turn.
    const double circumradius = 0.125 * std::sqrt(2.0);
    s.blocks.push_back(block(regular_polygon(4, circumradius, centre, turn - 0.75 * M_PI)));
  }
  return s;
}

}  // namespace dda::test
