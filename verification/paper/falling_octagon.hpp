// Table 1 of the paper: the falling octagon on a staircase of fixed blocks, for every
// treatment and the three time-step settings; area error against step, and the rock's path.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "kinematics/types.hpp"
#include "options.hpp"
#include "treatments.hpp"

namespace dda::paper {

struct FallingSample {
  int step;
  double time, area, rotation, omega;
  Vec2 centroid;
};

struct FallingRun {
  std::string treatment, setting;
  RunResult result;
  double initial_area = 0.0;
  std::vector<FallingSample> samples;  // every step, from step 0
  std::vector<std::pair<int, Polygon>> path;  // the rock's vertices every 20 steps (and the last)
  double turned = 0.0;  // sum over steps of |rotation increment| (rad): what inflates the area
};

// Runs every treatment (in smoke mode the first few) with every setting.
std::vector<FallingRun> run_falling(const Options& opt);

// falling_scene.csv, falling_area.csv, falling_path.csv, falling_summary.csv.
void write_falling_csv(const Options& opt, const std::vector<FallingRun>& runs);

// The Table 1 section of the report (markdown).
std::string falling_report(const Options& opt, const std::vector<FallingRun>& runs);

}  // namespace dda::paper
