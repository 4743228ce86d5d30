// The bolt force that gives a slope a target factor of safety (`dda fos --target-factor F`):
// every bolt of the scene set to hold one force T (pretension = yield force = T: an anchor
// held at its working load), the scene consolidated as dda fos consolidates it, and one
// strength-reduction trial at F; the smallest T whose trial stands, found by bisection.
// docs/factor-of-safety.md, "The bolt force for a target factor".
#pragma once

#include <string>
#include <vector>

#include "studies/strength_reduction.hpp"

namespace dda {

struct BoltForceTrial {
  double force = 0.0;  // N/m, each bolt's
  bool stable = false;
  std::string verdict;
  double largest_displacement = 0.0;  // m
};

struct BoltForceSearch {
  bool found = false;
  double target_factor = 0.0;
  double force = 0.0;        // N/m: the smallest force tried whose trial stood (found)
  double failing_force = 0.0;  // N/m: the largest force tried whose trial failed (0: none)
  std::vector<BoltForceTrial> trials;  // in the order run
  std::string message;       // why nothing was found (or "")
  bool interrupted = false;
};

// The search's bracket ends within `relative_tolerance` of its force (and within 1e-6 of the
// largest force when the force is 0). The largest force tried is the free blocks' weight
// (a bolt holding more than the whole slope weighs holds nothing a slope engineer needs).
inline constexpr double kBoltForceTolerance = 2e-3;

// `settings` as dda fos takes them (resolved per consolidation). The scene must have bolts.
BoltForceSearch find_bolt_force(const Scene& scene, const FosSettings& settings,
                                double target_factor, const StopQuery& stop = {});

// The scene with every bolt holding `force` (N/m): pretension = yield force = force; with
// force 0, the scene without its bolts.
Scene with_bolt_force(Scene scene, double force);

}  // namespace dda
