// `dda fos SCENE.json --out DIR`: consolidate the scene, search for its factor of
// safety by strength reduction (studies/strength_reduction.hpp), write the report and the
// pictures of the mechanism (docs/factor-of-safety.md).
#pragma once

#include <cstdint>
#include <string>

#include "studies/strength_reduction.hpp"

namespace dda {

// Returns the exit code: 0 with a factor, 3 without one or when the consolidation diverged.
// Throws InputError for a bad scene (exit 2) and std::runtime_error when the report cannot
// be written (exit 1).
// `method`: "strength-reduction" (the search, with the limit analysis beside it) or
// "limit-analysis" (the consolidation and the limit analysis only). `skip_limit_analysis`:
// the search alone (the report's limit_analysis says it was skipped). `dynamic_check`: after
// the search, dynamic trials at 0.95 F and 1.05 F (studies/factor_cross_check.hpp).
// What dda fos runs besides the search (its command-line flags).
struct FosCommandOptions {
  std::string method = "strength-reduction";  // or "limit-analysis" (that alone)
  bool skip_limit_analysis = false;  // --skip-limit-analysis
  bool dynamic_check = false;        // --dynamic-check: dynamic trials at 0.95 F and 1.05 F
  bool spread = false;               // --spread: the search again at dt / 5, x 5, penalty / 10, x 10
  // --target-factor F: instead of the search, the force each bolt must hold for the slope
  // to stand at F (studies/bolt_force_search.hpp); 0: not asked.
  double target_factor = 0.0;
  // --samples N: the probabilistic factor (studies/probabilistic_fos.hpp), N samples of the
  // scene's random_strengths drawn with --seed; 0: not asked. --at-factor F: one trial per
  // sample at F, its verdict, instead of each sample's search.
  long samples = 0;
  std::uint64_t seed = 0;
  double at_factor = 0.0;
  // --consolidated FILE: the consolidation a dda fos of the same scene wrote
  // (OUT/consolidated.ddack), read instead of consolidating again; empty: consolidate.
  std::string consolidated;
};

int fos_command(const std::string& scene_path, const std::string& out_dir, FosSettings settings,
                const FosCommandOptions& options = {});

}  // namespace dda
