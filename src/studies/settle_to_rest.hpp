// A consolidation that ends at rest, and how fast the model relaxes (docs/factor-of-safety.md,
// section 1, "Settling"). A static step starts from rest and solves (K + 2 M / dt^2) d = r
// for the out-of-balance force r; a free block with an out-of-balance acceleration a moves
// a dt^2 / 2 in it, so a step's displacement read against g dt^2 / 2 is the block's
// unbalanced force as a share of its weight, the ratio UDEC and FLAC converge on. Each
// static step leaves 1 / (1 + w^2 dt^2 / 2) of a mode w's out-of-balance force: a soft or
// deep model relaxes over many steps, and their number grows as 1 / dt^2. A consolidation
// fixed in seconds therefore ends far from rest at a short dt (the vertical cut at dt
// 0.002 s: still 16 % of gravity out of balance), and a trial fixed in seconds cannot tell
// a stable trial's relaxation from a failure. settle_to_rest runs static steps after the
// scene's own consolidation until every free block is in balance, and measures the
// relaxation's pace on the way; the trial time follows it (resolve_fos_settings).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "solver/run_stats.hpp"
#include "solver/world.hpp"

namespace dda {

struct SettlingSettings {
  // At rest: every free block's unbalanced acceleration (its static steps' net displacement
  // over the last 20 steps, over 20 g dt^2 / 2) below this share of g. 2e-5 is the
  // trial's own at-rest test (1 % of the speed limit of a 0.002 g mechanism,
  // studies/trial_watch.hpp), and of the order of UDEC's and FLAC's 1e-5.
  double rest_ratio = 2e-5;
  // The most static steps added: a slope that cannot stand at the consolidation's strength
  // is stopped earlier by the creep test (settle_to_rest), this bounds the rest. 20 000
  // static steps relax a mode that loses 1/e of its force in 2 000 steps by ten powers of e.
  int max_steps = 20000;
};

// What the settling did.
struct Settling {
  int steps = 0;                 // static steps added after the scene's own run
  bool at_rest = false;          // it ended with every free block in balance
  double unbalanced_start = 0.0; // the largest unbalanced ratio in its first step (share of g)
  double unbalanced_end = 0.0;   // ... over its last 20 steps
  // The steps over which the largest unbalanced ratio fell by a factor e, measured on the
  // way to rest (0: not measured, the consolidation was at rest or settled too fast to tell).
  double relaxation_steps = 0.0;
  std::string stopped;           // "at rest", "not settling" (creep), "step cap", "diverged: ..."
  // Whether the world was left where the settling ended. consolidate() puts back the
  // consolidation's own end when the settling was "not settling".
  bool kept = true;
  RunStats stats;                // the added steps' statistics
};

// Runs static steps (dynamic coefficient 0, the world's present gravity, joint laws and last
// time steps, no stages) on `world` until every free block is at rest, its motion stops
// decaying, or settings.max_steps. The stages are put back as they were (the trials read the
// scene's joint laws from them). `keep_going` (may be empty) is asked after every step.
Settling settle_to_rest(World& world, const SettlingSettings& settings,
                        const std::function<bool()>& keep_going = {});

// The unbalanced ratio of a static step, pure: the largest displacement of a free block's
// reference point in a step (a window's net displacement over its steps), over g dt^2 / 2.
double unbalanced_ratio(double largest_step_displacement, double gravity, double dt);

// The relaxation's pace from a settling's ratios, one per step (pure; exposed for tests):
// the steps over which the ratio falls by e between a window a quarter of the way in and
// the last window, or 0 when there are too few steps or the ratio did not fall.
double relaxation_steps_of(const std::vector<double>& ratios);

}  // namespace dda
