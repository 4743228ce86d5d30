// The iso-error maps' CSVs and report.md.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "maps.hpp"

namespace dda::constitutive {

struct Options {
  std::filesystem::path out;  // CSVs and report.md go here
  bool smoke = false;         // a 5 x 5 grid per map, for CI
  int n = 41;                 // grid points per side (odd)
  int substeps = 1000;        // sub-increments of the reference
  double min_timing_s = 0.02; // the one-call sweep is repeated at least this long
};

// What the report says about one map, beyond its points.
struct MapSummary {
  double max_error = 0.0;  // over the points where both converged
  double max_x = 0.0, max_y = 0.0;
  Branch max_branch = Branch::Elastic;      // the one call's branch there
  Branch max_ref_branch = Branch::Elastic;  // the reference's last branch there
  double max_within_1 = 0.0;                // over |x|, |y| <= 1
  double max_within_025 = 0.0;              // over |x|, |y| <= 0.25
  double max_absolute = 0.0;                // max ||s - s*|| / c (c: the cohesion at the start)
  int above_1pct = 0;                       // points with error > 1 %
  int plastic = 0;                          // points whose one call was not elastic
  int exact = 0;                            // of them, error <= 1e-12
  int failed_one = 0, failed_reference = 0;
  int count[6] = {0, 0, 0, 0, 0, 0};  // one-call branches, by Branch
  // Along the worst point's direction, the increment scaled by 2^-k, k = 0..6.
  std::vector<double> scaled_errors;
  // The reference at the worst point against one with 4x the sub-increments.
  double reference_check = 0.0;
};

MapSummary summarise(const MapResult& r);

// NAME.csv for one map:
// x,y,exx,eyy,gxy,sxx,syy,szz,sxy,ref_sxx,ref_syy,ref_szz,ref_sxy,error,branch,
// reference_branch,eps_p,reference_eps_p,status
void write_map_csv(const std::filesystem::path& dir, const MapResult& r);

// maps.csv: one row per map (name, title, axes, extent, the summary, the material, the start
// stress and the two directions), for the plots and check_projection.py.
void write_summary_csv(const std::filesystem::path& dir, const std::vector<MapResult>& maps,
                       const std::vector<MapSummary>& summaries);

std::string full_report(const Options& opt, const std::vector<MapResult>& maps,
                        const std::vector<MapSummary>& summaries, double wall_s);

}  // namespace dda::constitutive
