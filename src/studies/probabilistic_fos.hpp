// The probabilistic factor of safety (`dda fos SCENE --samples N --seed S`): the scene's
// random strengths (solver/random_strength_spec.hpp) drawn N times, and for each sample
// either one strength-reduction trial at a given F (its verdict: the fast estimate of the
// probability of failure) or the sample's own factor by the search of
// find_factor_of_safety. Every sample starts from the same consolidation
// (docs/factor-of-safety.md, "Probabilistic factor of safety").
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "studies/random_strengths.hpp"
#include "studies/strength_reduction.hpp"

namespace dda {

struct ProbabilisticSettings {
  long samples = 0;        // N >= 1
  std::uint64_t seed = 0;
  // > 0: one trial per sample at this F, its verdict (failing: the sample's factor is below
  // it). 0: the sample's factor by the search, whose first trial is at F = 1.
  double at_factor = 0.0;
  // This process runs the samples k with k % shares == share (the ranks of an MPI run share
  // the samples so); the others stay not done. 0 of 1: all of them.
  long share = 0;
  long shares = 1;
};

// What one sample gave.
struct SampleOutcome {
  long index = 0;
  std::vector<double> values;  // in the order of RandomStrengths::variables
  bool done = false;           // judged; false: not run or interrupted before a verdict
  // The verdict of the trial at at_factor (or, searching, of the search's trial at F = 1).
  bool failing = false;
  std::string verdict;
  // Searching: the sample's factor when the search found one.
  bool factor_found = false;
  double factor = 0.0;
  double last_stable = 0.0, first_failing = 0.0;
  std::string message;  // why no factor (search range exhausted)
  // Searching without a factor: no trial failed up to max_factor (above) or none stood down
  // to min_factor (below).
  bool above_range = false, below_range = false;
  int trials = 0;
  long steps = 0;
  double wall_time_s = 0.0;
};

// Over the judged samples.
struct ProbabilisticSummary {
  long judged = 0;
  long failing = 0;
  double probability_of_failure = 0.0;  // failing / judged
  ProportionInterval interval;          // Wilson 95 %
  // Searching: over the samples with a factor.
  long factors = 0;
  double mean_factor = 0.0;
  double factor_standard_deviation = 0.0;  // sample standard deviation (n - 1); 0 for n < 2
  double min_factor = 0.0, max_factor = 0.0;
  // Searching: samples whose search left the range (no failing F up to max_factor, or no
  // stable F down to min_factor).
  long above_range = 0, below_range = 0;
};

struct ProbabilisticResult {
  ProbabilisticSettings settings;
  double judged_at = 1.0;  // the F of the verdicts (at_factor, or 1 when searching)
  std::vector<SampleOutcome> samples;  // all N, in index order
  bool interrupted = false;
  ProbabilisticSummary summary;
};

ProbabilisticSummary summarise(const std::vector<SampleOutcome>& samples);

// Puts the outcomes of samples run elsewhere (their share of p.shares) into `result` at
// their indices, and judges the whole again: `interrupted` and the summary over all samples.
void add_samples(ProbabilisticResult& result, std::vector<SampleOutcome> outcomes);

// Runs the samples (those of p.share, when shared) on settings.jobs threads (each sample's trials one after another, so
// that a sample's search is the same whatever the number of threads; the search's own round
// width is one trial). `settings` resolved (resolve_fos_settings). `done` (may be empty) is
// called once per finished sample, one call at a time. `interrupted` and the summary are
// over this share's samples. Once `stop` (may be empty) says so,
// running samples end without a verdict and the rest are not started.
ProbabilisticResult run_probabilistic(const World& consolidated,
                                      const std::vector<JointMaterial>& scene_joints,
                                      const RandomStrengths& spec, const FosSettings& settings,
                                      const ProbabilisticSettings& p,
                                      const std::function<void(const SampleOutcome&)>& done,
                                      const StopQuery& stop = {});

}  // namespace dda
