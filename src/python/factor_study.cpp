#include "python/factor_study.hpp"

#include "io/input_error.hpp"
#include "python/simulation.hpp"
#include "studies/speculative_search.hpp"

namespace dda::python {

ConsolidatedScene consolidate_for_factor(const Scene& scene, const FosSettings& settings,
                                         const StopQuery& stop) {
  bool any_free = false;
  for (const BlockSpec& b : scene.blocks) any_free = any_free || !b.fixed;
  if (!any_free) throw InputError(scene.source + ": blocks: every block is fixed; nothing can fail");
  ConsolidatedScene c{consolidate(scene, settings.consolidation_factor,
                                  [&](const World&, const RunStats&) { return !(stop && stop()); }),
                      settings};
  if (c.consolidation.stats.diverged) {
    throw DivergedRun("the consolidation diverged at " + c.consolidation.stats.message +
                      "; no trial was run");
  }
  c.settings = resolve_fos_settings(c.consolidation.world, settings,
                                    c.consolidation.settling.relaxation_steps);
  return c;
}

FosResult search_factor(const ConsolidatedScene& c, const StopQuery& stop) {
  const World& world = c.consolidation.world;
  const FosSettings& settings = c.settings;
  return search_on_threads(
      settings, [&](double f, const StopQuery& trial_stop) { return run_trial(world, settings, f, trial_stop); },
      {}, stop);
}

ProbabilisticResult sample_factors(const Scene& scene, const ConsolidatedScene& c,
                                   const ProbabilisticSettings& p, const StopQuery& stop) {
  return run_probabilistic(c.consolidation.world, scene.joint_materials, scene.random_strengths,
                           c.settings, p, {}, stop);
}

}  // namespace dda::python
