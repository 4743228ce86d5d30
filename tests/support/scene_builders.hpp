// Small helpers for physics tests: scenes built as plain structs (no JSON), so the solver
// is tested on its own.
#pragma once

#include <cmath>

#include "solver/scene.hpp"

namespace dda::test {

inline Polygon rectangle(double x0, double y0, double w, double h) {
  return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
}

// Regular n-gon of circumradius r centred at c, first vertex at angle `phase`.
inline Polygon regular_polygon(int n, double r, Vec2 c = Vec2::Zero(), double phase = 0.0) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2.0 * M_PI * i / n;
    p.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
  }
  return p;
}

inline Polygon l_shape() { return {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}; }

// A scene with one elastic material ("rock": 2700 kg/m^3, 1 GPa, nu 0.25) and no blocks.
inline Scene base_scene(int steps, double dt) {
  Scene s;
  s.source = "test";
  s.materials.push_back(elastic_material("rock", 2700.0, 1e9, 0.25));
  s.control.time_steps = {dt};
  s.control.steps = steps;
  s.control.max_displacement_ratio = 1.0;
  return s;
}

inline BlockSpec block(Polygon vertices) {
  BlockSpec b;
  b.vertices = std::move(vertices);
  return b;
}

}  // namespace dda::test
