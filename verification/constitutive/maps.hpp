// Iso-error maps of the material library's return maps (docs/closed-forms.md,
// "Tangents and convergence"): from a stress on the yield surface, one strain increment
// from a grid, the stress of ONE call to integrate() against a reference of many
// sub-increments (successive calls with the state carried), mapped as the relative error
// ||s - s*|| / ||s*||.
#pragma once

#include <string>
#include <vector>

#include "materials/material.hpp"

namespace dda::constitutive {

// One map: a material, a start stress on its yield surface, two strain directions.
struct MapSpec {
  std::string name;   // file stem: NAME.csv, NAME.png
  std::string title;  // for the report and the plot
  std::string start;  // where on the surface the start stress lies, in words
  std::string flow;   // "associated", "non-associated (psi = 10)", ...
  MaterialParameters params;
  Vec4 start_stress = Vec4::Zero();  // (sxx, syy, szz, sxy), on the yield surface
  // The strain increment of grid point (x, y) is yield_strain (x dir_x + y dir_y), total
  // strain (exx, eyy, gxy) from the start (at zero strain, no plastic strain, eps_p 0).
  Vec3 dir_x = Vec3::Zero();
  Vec3 dir_y = Vec3::Zero();
  std::string x_label;
  std::string y_label;
  double yield_strain = 0.0;
  double extent = 5.0;  // x and y run over [-extent, extent]
};

// The maps of the report. e_y = c cos(phi) / (2 G): the deviatoric increment x = 1 along
// (1, -1, 0) raises the Mohr-circle radius by c cos(phi), the shear strength at zero mean
// stress; the three directions (1, -1, 0), (1, 1, 0), (0, 0, 2) all have the same tensor norm.
std::vector<MapSpec> make_maps();

// The norm of a stress as a tensor (the shear counts twice).
double stress_norm(const Vec4& s);

struct Point {
  double x = 0.0, y = 0.0;
  Vec3 strain = Vec3::Zero();
  MaterialResult one;   // one call
  Vec4 reference = Vec4::Zero();
  double reference_eps_p = 0.0;
  Branch reference_branch = Branch::Elastic;  // of the last sub-increment
  bool reference_ok = true;                   // every sub-increment converged
  double error = 0.0;  // ||s - s*|| / ||s*||; NaN when either failed
};

struct MapResult {
  MapSpec spec;
  int n = 0;  // grid points per side
  int substeps = 0;
  std::vector<Point> points;  // row-major: y outer, x inner
  double ns_per_call = 0.0;            // the one-call sweep, repeated for a stable timing
  double ns_per_reference_call = 0.0;  // the reference's sub-increment calls
  double surface_residual = 0.0;       // |f(start)| / strength: the start is on the surface
};

// The stress after `substeps` equal sub-increments up to total strain `strain`.
struct Reference {
  Vec4 stress = Vec4::Zero();
  double eps_p = 0.0;
  Branch branch = Branch::Elastic;
  bool ok = true;
};
Reference sub_incremented(const MapSpec& spec, const Vec3& strain, int substeps);

// The strain increment of grid point (x, y): yield_strain (x dir_x + y dir_y).
Vec3 grid_strain(const MapSpec& spec, double x, double y);

// ||s - s*|| / ||s*|| of a one-call stress against the reference; NaN when either failed.
double map_error(const MaterialResult& one, const Reference& reference);

// One call from the start against `substeps` sub-increments, at total strain `strain`.
double one_call_error(const MapSpec& spec, const Vec3& strain, int substeps);

// Every grid point of a map: n per side over [-extent, extent] (n odd, so 0 is on it).
MapResult compute_map(const MapSpec& spec, int n, int substeps, double min_timing_s);

// The yield function at the start, relative to the strength (c cos phi for MC, xi c for DP).
double start_yield_residual(const MapSpec& spec);

}  // namespace dda::constitutive
