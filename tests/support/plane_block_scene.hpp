// A block resting on a fixed plane inclined at `dip` degrees, its joint of friction angle
// phi and no cohesion (Coulomb slip), and optionally random_strengths drawing phi from
// N(mean, sd): the limit-equilibrium case of the probabilistic factor of safety, whose
// factor is tan(phi) / tan(dip) and P(F < 1) = Phi((dip - mean) / sd). A static stage
// ramps gravity up for the consolidation. Shared by tests/studies and tests/app.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

namespace dda::test {

inline nlohmann::json plane_block_scene(double dip, double phi, double base = 2.0, double height = 0.5) {
  using json = nlohmann::json;
  const double a = dip * M_PI / 180.0;
  const double tx = std::cos(a), ty = std::sin(a), nx = -ty, ny = tx;
  auto at = [&](double s, double q) { return json::array({s * tx + q * nx, s * ty + q * ny}); };
  return {
      {"gravity", {0.0, -9.81}},
      {"control", {{"time_step", 0.002}, {"max_displacement_ratio", 0.001}}},
      {"materials", {{"rock", {{"model", "elastic"}, {"density", 2500.0}, {"young", 1e10}, {"poisson", 0.25}}}}},
      {"joint_materials",
       {{"default", {{"friction_angle", phi}, {"cohesion", 0.0}, {"tensile_strength", 0.0}, {"law", "coulomb_slip"}}}}},
      {"blocks",
       {{{"vertices", {at(-2, 0), at(-2, -1), at(6, -1), at(6, 0)}}, {"material", "rock"}, {"fixed", true}},
        {{"vertices", {at(1, 0), at(1 + base, 0), at(1 + base, height), at(1, height)}}, {"material", "rock"}}}},
      {"stages", {{{"duration", 0.5}, {"dynamic_coefficient", 0.0}, {"gravity_ramp", {0.0, 1.0}}}}},
  };
}

// The scene's default joint's friction angle drawn from N(mean, sd), truncated to [min, max].
inline nlohmann::json with_random_friction(nlohmann::json scene, double mean, double sd, double min,
                                           double max) {
  scene["random_strengths"] = {
      {"variables",
       {{{"joint_material", "default"}, {"property", "friction_angle"}, {"distribution", "normal"},
         {"mean", mean}, {"standard_deviation", sd}, {"min", min}, {"max", max}}}}};
  return scene;
}

}  // namespace dda::test
