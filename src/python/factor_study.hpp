// The factor of safety from Python (dda.fos, dda.fos_samples): the scene consolidated as
// `dda fos` consolidates it, the automatic settings resolved from that state, then the
// strength-reduction search (studies/speculative_search.hpp) or the samples of the scene's
// random strengths (studies/probabilistic_fos.hpp). Pure C++: the bindings release the GIL
// around it and hand it the stop query that Ctrl-C answers.
#pragma once

#include <string>

#include "python/signal_watch.hpp"
#include "solver/scene.hpp"
#include "studies/probabilistic_fos.hpp"
#include "studies/strength_reduction.hpp"

namespace dda::python {

// The consolidation every trial starts from and the settings resolved on it.
struct ConsolidatedScene {
  Consolidation consolidation;
  FosSettings settings;  // resolved (failure displacement, trial time)
};

// Throws InputError when every block is fixed, DivergedRun when the consolidation fails.
// A stop during it returns with consolidation.stats.interrupted.
ConsolidatedScene consolidate_for_factor(const Scene& scene, const FosSettings& settings,
                                         const StopQuery& stop);

// The search from the consolidated state, settings.jobs trials at once.
FosResult search_factor(const ConsolidatedScene& c, const StopQuery& stop);

// N samples of the scene's random strengths (the scene must have some).
ProbabilisticResult sample_factors(const Scene& scene, const ConsolidatedScene& c,
                                   const ProbabilisticSettings& p, const StopQuery& stop);

}  // namespace dda::python
