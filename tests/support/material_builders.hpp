// The soil-like parameter set the material tests share (E = 50 MPa, nu = 0.3, c = 20 kPa,
// phi = 30 degrees, 2000 kg/m^3), and a path segment builder for the material-point driver.
#pragma once

#include <optional>

#include "materials/material.hpp"
#include "materials/material_point.hpp"

namespace dda::test {

inline MaterialParameters soil(MaterialModel model, double dilation_deg) {
  MaterialParameters p;
  p.young = 50e6;
  p.poisson = 0.3;
  p.density = 2000.0;
  if (model == MaterialModel::DruckerPrager)
    p.model_parameters = plastic_parameters<DruckerPragerParameters>(20e3, 30.0, dilation_deg);
  else if (model == MaterialModel::MohrCoulomb)
    p.model_parameters = plastic_parameters<MohrCoulombParameters>(20e3, 30.0, dilation_deg);
  return p;
}

// Makes `p` a material of `model`, its own parameters at their defaults (zero strength).
inline void set_model(MaterialParameters& p, MaterialModel model) {
  if (model == MaterialModel::DruckerPrager)
    p.model_parameters = DruckerPragerParameters{};
  else if (model == MaterialModel::MohrCoulomb)
    p.model_parameters = MohrCoulombParameters{};
  else
    p.model_parameters = ElasticOnly{};
}

// The model's own parameters of `p` (which must be of that model), to change one.
inline MohrCoulombParameters& mohr_coulomb_of(MaterialParameters& p) {
  return std::get<MohrCoulombParameters>(p.model_parameters);
}
inline DruckerPragerParameters& drucker_prager_of(MaterialParameters& p) {
  return std::get<DruckerPragerParameters>(p.model_parameters);
}
inline const MohrCoulombParameters& mohr_coulomb_of(const MaterialParameters& p) {
  return std::get<MohrCoulombParameters>(p.model_parameters);
}
inline const DruckerPragerParameters& drucker_prager_of(const MaterialParameters& p) {
  return std::get<DruckerPragerParameters>(p.model_parameters);
}
// The strength of a plastic `p` (to read or change one).
inline FrictionalStrength& strength_of(MaterialParameters& p) { return *frictional_strength(p); }
inline const FrictionalStrength& strength_of(const MaterialParameters& p) {
  return *frictional_strength(p);
}

inline PathSegment segment(int steps, std::optional<ComponentTarget> xx,
                           std::optional<ComponentTarget> yy, std::optional<ComponentTarget> xy) {
  PathSegment s;
  s.steps = steps;
  s.targets = {xx, yy, xy};
  return s;
}

}  // namespace dda::test
