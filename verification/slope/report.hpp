// The slope verification's output: slope.csv, report.json, report.md and, per case, the
// mechanism's outlines (mechanism_<case>.json) that plot_slope.py draws.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "slope_cases.hpp"
#include "slope_run.hpp"

namespace dda::slope {

struct RunInfo {
  bool smoke = false;
  double tolerance = 0.01;
  int jobs = 2;
  double detect_acceleration = 0.002;
  double dynamic_coefficient = 0.0;  // the trials'
  double wall_s = 0.0;
  bool spread = false;  // --spread: each case also at kSpreadSettings
};

// One progress line for a finished case.
std::string case_line(const SlopeCase& c, const CaseResult& r);

// Writes slope.csv, report.json, report.md and the mechanism files into `dir`; returns the
// report's markdown. Throws std::runtime_error naming a file it cannot write.
std::string write_reports(const std::filesystem::path& dir, const RunInfo& info,
                          const std::vector<SlopeCase>& cases, const std::vector<CaseResult>& results);

}  // namespace dda::slope
