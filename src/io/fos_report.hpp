// The report of `dda fos`: DIR/report.json (the contract: factor_of_safety,
// bracket, trials with F and stable; docs/factor-of-safety.md) and DIR/report.md, the same
// for a reader.
#pragma once

#include <filesystem>
#include <string>

#include "solver/scene.hpp"
#include "studies/consolidation_bonds.hpp"
#include "studies/factor_cross_check.hpp"
#include "studies/limit_analysis.hpp"
#include "studies/probabilistic_fos.hpp"
#include "studies/settings_spread.hpp"
#include "studies/trial_mechanism.hpp"
#include "studies/strength_reduction.hpp"

namespace dda {

// What the consolidation at F = 1 did before the trials.
struct ConsolidationInfo {
  int steps = 0;
  double time = 0.0;         // s, simulated
  double wall_time_s = 0.0;
  double kinetic_end = 0.0;  // J/m, left at its end (the trials start from rest)
  // Bonds it broke, and where (RunStats::broken_bonds: the first 1000).
  long bonds_broken = 0;
  std::vector<BrokenBond> broken_bonds;
  double factor = 1.0;  // the joints' strengths were divided by this
  // The broken bonds against an elastic solution (not computed when none broke).
  BondCheck bond_check;
  // The static steps that brought it to rest after the scene's own run, and the pace of
  // that relaxation (studies/settle_to_rest.hpp).
  Settling settling;
};

// The second factor beside the search: the rigid-block limit analysis of the consolidated
// scene, and each free block's own bound (studies/limit_analysis.hpp).
struct LimitAnalysisInfo {
  std::string method;  // "strength-reduction" (the search, the analysis beside it) or "limit-analysis"
  LimitAnalysisResult analysis;
  std::vector<BlockBound> single_block_bounds;  // smallest first
  // The first failing trial's mechanism and its group's own bound, when a factor was found.
  bool has_failing = false;
  double failing_factor = 0.0;
  TrialMechanism failing;
};

// Writes DIR/report.json and DIR/report.md (creating DIR). Throws std::runtime_error naming
// the path when it cannot. `limit` may be null (the analysis was not reached); `dynamic` is
// null unless --dynamic-check ran, `spread` unless --spread did, `probabilistic` unless
// --samples did (then report.json gains "probabilistic" and report.md leads with it).
void write_fos_report(const std::filesystem::path& dir, const Scene& scene,
                      const FosSettings& settings, const ConsolidationInfo& consolidation,
                      const FosResult& result, double wall_time_s,
                      const LimitAnalysisInfo* limit = nullptr,
                      const DynamicCheck* dynamic = nullptr,
                      const SettingsSpread* spread = nullptr,
                      const ProbabilisticResult* probabilistic = nullptr);

// The consolidation's broken bonds against the elastic solution, one line (no newline):
// "of the 118 bonds the consolidation broke, 95 are overstressed ...".
std::string bond_check_line(const BondCheck& check);

// The settling after the consolidation, a phrase (no newline) for the report and the
// command line: "; then 212 static steps to rest (an e-fold of the relaxation in 44 steps)".
std::string settling_phrase(const Settling& settling);

// One line on the limit analysis, as dda fos prints it.
std::string limit_analysis_line(const LimitAnalysisInfo& limit);
// One line on the first failing trial's mechanism (limit.has_failing), naming the joints
// its blocks slip on and open by the scene's joint material names.
std::string failing_mechanism_line(const LimitAnalysisInfo& limit, const Scene& scene);

// One line per finished trial, as the progress shows it:
// "trial F = 1.250: stable (came to rest), largest displacement 0.0021 m, 812 steps, 3.2 s".
std::string trial_line(const TrialResult& t);

}  // namespace dda
