// The factor-of-safety search on threads that never wait for one another: the search of
// find_factor_of_safety (the same trials, the same verdicts, the same factor), with a thread
// that has finished its trial starting the trial the search would ask for next if the trials
// still running end as predicted (docs/factor-of-safety.md, section 3).
//
// Why: a round of the search waits for its slowest trial, and near the factor a failing trial
// runs to half the trial time while a stable one comes to rest early, so one core idled for
// most of each round. The search itself stays a pure function of the verdicts: a trial the
// prediction got wrong is stopped and dropped, never used, so the factor does not depend on
// which trial ends first, on the machine's speed or on the number of threads beyond the
// search's round width (settings.jobs).
#pragma once

#include <functional>
#include <vector>

#include "studies/strength_reduction.hpp"

namespace dda {

// One trial at F; it ends early (marked interrupted) when `stop` says so.
using TrialRunner = std::function<TrialResult(double factor, const StopQuery& stop)>;

// The verdict the search assumes for a trial not yet judged, to plan ahead of it: stable when
// a judged (or assumed) stable trial lies at or above F (verdicts monotone in F) or when F is
// at most the consolidation's factor (the slope came to rest there); failing otherwise,
// because failing trials are the slow ones, so the trial still running is most likely the
// failing one. `known` are the trials judged or assumed so far.
bool predicted_stable(double factor, const std::vector<TrialResult>& known,
                      double consolidation_factor);

// The factors to run next, in order of need: first the unjudged trials of the search's
// current round (next_factors over the judged trials), then, assuming predicted_stable for
// every trial not yet judged, those of the rounds after it, until `threads` unjudged factors
// are listed or the planned search ends. `judged` holds every trial judged so far, in or out
// of the search's path (a trial's verdict depends on its F only). `done` is true when the
// search needs no more trials; `path` holds the trials of the search's rounds judged in
// full, in the order find_factor_of_safety would have run them (all of them when done), and
// `frontier` the factors of the first round not judged in full. Exposed for tests.
struct SearchPlan {
  bool done = false;
  std::vector<double> wanted;       // unjudged factors, most needed first
  std::vector<TrialResult> path;
  std::vector<double> frontier;
};
SearchPlan plan_search(const std::vector<TrialResult>& judged, const FosSettings& settings,
                       int threads);

// The search of find_factor_of_safety(settings, ...) on settings.jobs threads, each starting
// the next wanted trial of plan_search as soon as it is free, and stopping (and dropping) a
// running trial the plan no longer wants. `done` (may be empty) is called once per judged
// trial, one call at a time; dropped trials are not reported. `stop` (may be empty) ends the
// search as find_factor_of_safety's interrupted round does. The result's trials are the
// search's path; discarded_trials and discarded_wall_time_s count what was dropped.
FosResult search_on_threads(const FosSettings& settings, const TrialRunner& run,
                            const std::function<void(const TrialResult&)>& done,
                            const StopQuery& stop = {});

}  // namespace dda
