// The soil-like parameter set the material tests share (E = 50 MPa, nu = 0.3, c = 20 kPa,
// phi = 30 degrees, 2000 kg/m^3), and a path segment builder for the material-point driver.
#pragma once

#include <optional>

#include "materials/material.hpp"
#include "materials/material_point.hpp"

namespace dda::test {

inline MaterialParameters soil(MaterialModel model, double dilation_deg) {
  MaterialParameters p;
  p.model = model;
  p.young = 50e6;
  p.poisson = 0.3;
  p.density = 2000.0;
  p.cohesion = 20e3;
  p.friction_angle = 30.0;
  p.dilation_angle = dilation_deg;
  return p;
}

inline PathSegment segment(int steps, std::optional<ComponentTarget> xx,
                           std::optional<ComponentTarget> yy, std::optional<ComponentTarget> xy) {
  PathSegment s;
  s.steps = steps;
  s.targets = {xx, yy, xy};
  return s;
}

}  // namespace dda::test
