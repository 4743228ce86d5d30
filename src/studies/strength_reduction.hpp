// Factor of safety by strength reduction (`dda fos`): the joints' strengths (and,
// when asked, plastic blocks' strengths) divided by a trial factor F, a run (static by
// default) from the consolidated scene, a verdict (stable or failing) after a bounded number
// of steps, and a search for the F between the last stable and the first failing trial
// (docs/factor-of-safety.md).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "contact/joint_law.hpp"
#include "materials/material.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"
#include "studies/settle_to_rest.hpp"

namespace dda {

// ---- strength reduction (pure) ----

// tan(phi)/F, c/F, tensile strength/F; the law's kind is kept. F > 0.
JointLaw reduced_joint_law(const JointLaw& law, double factor);
// A plastic material's cohesion (and its hardening curve), tan(friction angle) and tensile
// strength divided by F; the dilation angle is kept, but never above the reduced friction
// angle (the material library requires psi <= phi). F > 0.
MaterialParameters reduced_material(const MaterialParameters& m, double factor);

// ---- one trial ----

// How a trial runs and is judged. Units SI; defaults resolved by resolve_fos_settings.
struct FosSettings {
  // The search: it stops when the bracket [last stable F, first failing F] is no wider than
  // this (absolute, in F). Range (0, 1].
  double tolerance = 0.01;
  // Search range: no failing F up to max_factor, or no stable F down to min_factor, ends the
  // search without a factor (exit 3). 0 < min_factor < 1 < max_factor.
  double min_factor = 0.1;
  double max_factor = 10.0;
  // A trial fails when a watched point moves more than this (m) from where the trial
  // started. <= 0: auto, 0.05 x sqrt(median area of the free blocks).
  double failure_displacement = 0.0;
  // Simulated time of a stable trial (s). <= 0: auto, sqrt(2 d / (a g)) with d the failure
  // displacement and a = detect_acceleration: a point accelerating at a g from rest moves d
  // in that time.
  double trial_time = 0.0;
  // The automatic trial time is at least this many of the model's relaxation e-folds
  // (Settling::relaxation_steps, measured as the consolidation settles) times the trial's
  // time step: a static trial moves towards equilibrium at the pace the consolidation
  // settled at, in steps, whatever dt is. 20: the 3-cell vertical cut of
  // verification/vertical-cut relaxes by e in 44 steps at dt 0.01 s, and its stable trials
  // near the factor needed 9 s (20 e-folds) to come to rest; the 5-cell mesh (68 steps)
  // called some failing after 2.26 s (3 e-folds). A floor, not a convergence test: near the
  // factor a plastic model relaxes ever more slowly (docs/factor-of-safety.md, section 6).
  double relaxations_per_trial = 20.0;
  // A damped trial still moving at T/2 or at T is judged by where its decay takes it
  // (TrialWatch::predicted_displacement): failing beyond the failure displacement, or when it
  // does not lose 1/e of its speed within this many steps. <= 0: auto, relaxations_per_trial
  // e-folds of the consolidation's relaxation when the settling measured one, else the
  // trial's own length in steps. In steps, not seconds: a static trial relaxes at a pace in
  // steps whatever dt is, so the verdict neither follows dt nor the trial time.
  double decay_horizon_steps = 0.0;
  // The smallest acceleration, as a share of |gravity|, that the auto trial time resolves
  // (range (0, 1)). 0.002: on a 30-degree plane, a block whose reduced strength falls short
  // of its driving force by 0.4 % accelerates at 0.002 g (docs/factor-of-safety.md).
  double detect_acceleration = 0.002;
  // Share of the velocity carried from step to step in a trial (the scene's own
  // dynamic_coefficient applies to the consolidation only), range [0, 1]. 0 (default):
  // static trials, as strength reduction asks for the static limit; 1: dynamic
  // (docs/factor-of-safety.md, "Static or dynamic trials").
  double dynamic_coefficient = 0.0;
  // Also reduce the strengths of plastic blocks' materials.
  bool reduce_materials = false;
  // Trials run at once (threads): the search evaluates this many factors per round.
  int jobs = 2;
  // The consolidation runs with the joints' strengths divided by this (1: the scene's own).
  // A slope whose factor is below 1 cannot come to rest at full strength; consolidating it
  // at, say, 0.5 (double strength) gives the trials a state at rest. Range (0, 1].
  double consolidation_factor = 1.0;
  // Pseudo-static earthquake load: a horizontal body force of this share of each block's
  // weight, along +x (negative: along -x; give the sign that points out of the slope), as
  // limit-equilibrium programs apply a seismic coefficient. It acts from the consolidation
  // on (with_seismic_coefficient). Range [-1, 1].
  double seismic_coefficient = 0.0;
  // A factor the slope is expected to fail at, tried before the search doubles (or halves)
  // past it: dda fos gives the limit analysis's upper end, an upper bound of the factor of a
  // slope whose joints do not dilate. A bracket then starts below it instead of at 2, which
  // saves the search's most expensive trials (failing ones, far above the factor). <= 0:
  // none. It only places trials: every verdict is a trial's.
  double first_failing_guess = 0.0;
};

// The scene with the seismic coefficient kh as part of its gravity: g + kh |g| x (a
// constant body force, so the energy account books it as it books gravity, and a stage's
// gravity ramp ramps both).
Scene with_seismic_coefficient(Scene scene, double kh);

// What one trial found.
struct TrialResult {
  double factor = 0.0;
  bool stable = false;
  // Why: "at rest" (stopped early: nothing sliding, every watched point still),
  // "did not fail within the trial time", "coming to rest short of the failure
  // displacement" (a damped trial whose end speed is above end_speed_limit but whose motion
  // decays so that predicted_displacement is below d), "still moving at the end" (end speed
  // above end_speed_limit, not so decaying), "moving faster than the speed limit" (a damped trial, stopped early;
  // studies/trial_watch.hpp),
  // "moved beyond the failure displacement", "diverged: ...".
  std::string verdict;
  double largest_displacement = 0.0;  // m, of the watched points since the trial started
  // m/s, the fastest watched point at the trial's end, as a mean over a window: its
  // displacement over the trial's last quarter, or over the last 20 steps when the trial
  // stopped before that quarter (failing or at rest), divided by the window's time.
  double end_speed = 0.0;
  // m/s, the speed above which the end speed means failing: d / T in a dynamic trial; in a
  // damped one (dynamic coefficient k < 1) the steady speed of a mechanism accelerating at
  // detect_acceleration g, a g dt (1 + k) / (2 (1 - k)) over the window's mean step dt.
  double end_speed_limit = 0.0;
  // m, where a damped trial's motion was heading at its end: the largest displacement plus
  // the rest of its decay (TrialWatch::predicted_displacement; infinite when not decaying);
  // nullopt in dynamic trials and trials shorter than a quarter of T.
  std::optional<double> predicted_displacement;
  double kinetic_peak = 0.0;          // J/m, the largest kinetic energy during the trial
  double kinetic_end = 0.0;           // J/m, at its end
  int steps = 0;
  // The trial's step statistics (cuts by reason, linear solves, open-close iterations):
  // what its steps cost.
  RunStats stats;
  double simulated_time = 0.0;        // s
  double wall_time_s = 0.0;
  int watched_point = -1;             // monitor index (monitors given) or block index that moved most
  // Stopped by the caller (StopQuery) before a verdict: `verdict` is "interrupted" and
  // `stable` false, and the search leaves the trial out of its bracket.
  bool interrupted = false;
  World world;                        // the state where the trial ended (for pictures)
};

// The scene run as `dda run` runs it (its control and stages), with every joint material's
// strength, and every stage's replacement of it, divided by settings.consolidation_factor;
// afterwards the world carries the scene's own joint laws again, for the trials. `observe`
// as for run().
// It then settles (settle_to_rest): static steps until every free block is in balance, so
// that a trial sees what its reduced strengths do and not what is left of the scene's own
// run, and the pace of that relaxation is measured for the trial time.
struct Consolidation {
  World world;
  RunStats stats;
  Settling settling;
};
Consolidation consolidate(const Scene& scene, double consolidation_factor,
                          const StepObserver& observe);

// The scene's joint laws as given (a staged consolidation may have replaced them for its
// stages; the trials start from the scene's).
std::vector<JointLaw> scene_joint_laws(const World& consolidated);

// The median area of the world's free blocks (m^2): the typical block size the automatic
// failure displacement and the mechanism pictures take. The world must have a free block.
double median_free_block_area(const World& world);

// Fills the automatic settings (failure_displacement, trial_time) from the consolidated
// world and the relaxation's pace its settling measured (steps per e-fold, 0: none
// measured; Settling::relaxation_steps). The world must have at least one free block.
FosSettings resolve_fos_settings(const World& consolidated, FosSettings settings,
                                 double relaxation_steps = 0.0);

// Asked after every step of a trial: true stops it (dda fos: SIGINT or SIGTERM).
using StopQuery = std::function<bool()>;

// Runs one trial: a copy of `consolidated` with every joint's strength divided by `factor`
// (and plastic blocks' when settings.reduce_materials), the scene's last time steps, the
// trial's dynamic coefficient, until it fails or trial_time has passed. Settings resolved.
// `stop` (may be empty) ends it early, marked interrupted.
TrialResult run_trial(const World& consolidated, const FosSettings& settings, double factor,
                      const StopQuery& stop = {});

// Runs the trials at `factors`, up to settings.jobs at once (threads, each trial with its
// own copy of the world), and returns them in the order of `factors`. `done` (may be
// empty) is called once per finished trial, one call at a time. Once `stop` (may be empty)
// says so, running trials end interrupted and those not started are returned interrupted
// with no step.
std::vector<TrialResult> run_trials(const World& consolidated, const FosSettings& settings,
                                    const std::vector<double>& factors,
                                    const std::function<void(const TrialResult&)>& done,
                                    const StopQuery& stop = {});

// ---- the search (pure over an evaluator) ----

// Evaluates trials at the given factors (at once, when it can) and returns them in order.
using TrialEvaluator = std::function<std::vector<TrialResult>(const std::vector<double>&)>;

struct FosResult {
  bool found = false;
  double factor_of_safety = 0.0;  // the bracket's midpoint
  double last_stable = 0.0;       // the bracket
  double first_failing = 0.0;
  std::string message;            // why none was found, or a note (non-monotone verdicts)
  std::vector<TrialResult> trials;  // in the order they ran
  // The search stopped before its end (a trial came back interrupted): not found, and the
  // bracket of the trials judged so far, when they have one, in last_stable/first_failing
  // with has_bracket.
  bool interrupted = false;
  bool has_bracket = false;
  // Trials a search on threads started ahead of a verdict and dropped when the verdict went
  // the other way (studies/speculative_search.hpp): how many, and their wall time (s).
  int discarded_trials = 0;
  double discarded_wall_time_s = 0.0;
};

// The next factors to try given the trials so far: from F = 1 (and, with more jobs, F = 2)
// outwards by doubling (halving) until a bracket exists, then `jobs` points that cut the
// bracket into jobs + 1 equal parts. Empty when the bracket is within the tolerance or the
// range is exhausted. Exposed for tests.
std::vector<double> next_factors(const std::vector<TrialResult>& trials, const FosSettings& s);

// Runs the search; always ends: each round either narrows the bracket by a factor of
// jobs + 1 or moves a search end by a factor of 2 towards the range's limits.
// A round that returns an interrupted trial ends it, interrupted.
FosResult find_factor_of_safety(const FosSettings& settings, const TrialEvaluator& evaluate);

// The search's result from its trials (in the order they ran): the bracket, the factor and
// the message; `interrupted` when a trial came back interrupted and the search stopped.
FosResult conclude_search(std::vector<TrialResult> trials, bool interrupted,
                          const FosSettings& settings);

}  // namespace dda
