// The cases of the slope verification: each a scene built in code, its
// limit-equilibrium factor from limit_equilibrium.hpp, the published value it is checked
// against, and the resolution within which a strength-reduction search can find it (README
// "Tolerances"). Shared by dda_verify_slope and
// tests/verification/test_slope_verification.cpp.
#pragma once

#include <string>
#include <vector>

#include "limit_equilibrium.hpp"

namespace dda::slope {

struct SlopeCase {
  std::string name;   // identifier: file names, --case
  std::string title;  // one line for the report
  double published = 0.0;        // Hoek & Bray's value (for checking only)
  int published_decimals = 3;    // the precision it is given to
  double le_factor = 0.0;        // from the closed form (limit_equilibrium.cpp)
  // The F beyond the limit-equilibrium factor at which the mechanism's out-of-balance force
  // reaches 2 x detect_acceleration x its moving weight: what a trial's verdict may miss.
  double resolution = 0.0;
  bool needs_water = false;      // the scene has the "water" key
  bool in_smoke = false;         // part of --smoke
  std::string scene;             // JSON text for dda::parse_scene_text
  // Toppling only: the columns' block indices from the toe, and their limit-equilibrium modes.
  std::vector<int> columns;
  std::vector<std::string> le_modes;
  double limiting_friction = 0.0;  // degrees (toppling), 0 otherwise
  // dda fos's --seismic-coefficient for the case (FosSettings::seismic_coefficient; 0: none).
  double seismic_coefficient = 0.0;
};

// Every case, in report order. `detect_acceleration`: the trials' (FosSettings), which sets
// the resolution.
std::vector<SlopeCase> all_cases(double detect_acceleration);

// The published cases' data, for the tests of the closed forms.
PlaneBlock planar_block(double cohesion_kpa, double uplift_kn);
TensionCrackSlope hoek_bray_slope(double water_depth);
BiplanarWedge biplanar_wedge(double interface_friction);
ToppleSlope goodman_bray_slope();
inline constexpr double kToppleFriction = 45.0;  // degrees: the DDA case's friction angle

}  // namespace dda::slope
