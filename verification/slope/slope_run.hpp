// One slope case through DDA: the scene parsed, consolidated at F = 1 (its static stage), the
// strength-reduction search (studies/strength_reduction.hpp), and what the first failing trial
// shows of the mechanism. Shared by dda_verify_slope and the tests.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "kinematics/types.hpp"
#include "slope_cases.hpp"
#include "studies/settings_spread.hpp"

namespace dda::slope {

struct RunOptions {
  int jobs = 2;             // trials at once (threads)
  double tolerance = 0.01;  // the search's bracket width
  double dynamic_coefficient = 0.0;  // the trials' (FosSettings); 0: static, the default
  // The scene's time steps and its penalty (auto when it gives none) multiplied by these:
  // the spread of the factor over the settings (--spread).
  double time_step_scale = 1.0;
  double penalty_scale = 1.0;
};

// A toppling column at the first failing trial (moved against the consolidated state).
struct ColumnMotion {
  int column = 0;               // 1 = the toe column
  double rotation_deg = 0.0;    // counter-clockwise: towards the toe
  double base_slip = 0.0;       // m, the toe-side base corner's displacement
  double top_move = 0.0;        // m, the toe-side top corner's displacement
  std::string mode;             // stable / topple / slide (README "Toppling modes")
  std::string le_mode;
};

struct CaseResult {
  std::string name;
  bool skipped = false;     // not run (water pressure not available)
  std::string note;         // why skipped, or the search's message
  bool found = false;
  double factor = 0.0;      // the bracket's midpoint
  double last_stable = 0.0, first_failing = 0.0;
  double error = 0.0;       // factor - le_factor
  double allowed = 0.0;     // tolerance / 2 + resolution
  bool pass = false;
  double wall_s = 0.0;      // consolidation and search
  // Rigid-block limit analysis of the consolidated blocks (studies/limit_analysis.hpp):
  // found, its bracket [la_factor, la_upper], or why it was not computed.
  bool la_found = false;
  double la_factor = 0.0, la_upper = 0.0;
  std::string la_note;
  int trials = 0;
  double failure_displacement = 0.0, trial_time = 0.0;  // the resolved settings
  // The block outlines, consolidated and at the end of the first failing trial.
  std::vector<Polygon> before, after;
  std::vector<bool> fixed;
  std::vector<ColumnMotion> columns;  // toppling only
  // Toppling only (README "Toppling: the interface that does not slip"): the share of the
  // limiting friction each column interface (columns n, n + 1: element n - 1) carries at the
  // end of the first failing trial, sum |S| / (tan phi_F sum N) over its contacts (1 where
  // it carries no normal force); the tabular method's factor with those shares; DDA's
  // factor less that one. The case passes when that difference is within `allowed`.
  std::vector<double> interface_shares;
  double le_mobilised = 0.0;
  double error_mobilised = 0.0;
  // Toppling only: trials every 0.05 in F from 1 up to the search's first failing F, to see
  // whether the verdicts are monotone (the search assumes they are).
  struct ScanPoint {
    double factor = 0.0;
    bool stable = false;
    double moved = 0.0;  // m, the largest watched displacement
  };
  std::vector<ScanPoint> scan;
  // --spread: the factor at each of kSpreadSettings (0 where none was found), and the
  // spread of all five, (max - min) / mean (0 when fewer than two were found).
  std::vector<double> spread_factors;
  double spread = 0.0;
};

// Runs `c`. A case that needs the "water" key is skipped, with a note, when the scene reader
// does not know it. `progress` (may be empty) gets one line per trial.
CaseResult run_case(const SlopeCase& c, const RunOptions& options,
                    const std::function<void(const std::string&)>& progress);

}  // namespace dda::slope
