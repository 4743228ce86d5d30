// The factor of safety over the time step and the penalty (`dda fos --spread`,
// verification/slope --spread): the same scene searched again with every time step divided
// and multiplied by 5 and the penalty divided and multiplied by 10. A factor that moves by
// more than kSpreadAgreement over these is a property of the model's numbers as much as of
// the slope, and the report says so. docs/factor-of-safety.md, section 6.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "solver/scene.hpp"
#include "studies/strength_reduction.hpp"

namespace dda {

struct SpreadSetting {
  const char* name;
  double time_step_scale;  // every time step of the scene and of its stages times this
  double penalty_scale;    // the penalty ("auto" resolved) times this
};

// dt 0.002 to 0.05 s about a scene's 0.01 s, and a decade of penalty either way of "auto":
// the range over which a factor must hold.
inline constexpr SpreadSetting kSpreadSettings[] = {
    {"dt/5", 0.2, 1.0}, {"dt*5", 5.0, 1.0}, {"penalty/10", 1.0, 0.1}, {"penalty*10", 1.0, 10.0}};

// A factor that moves by more than this share (max - min over the mean) is reported as
// depending on the settings: the 2 % a slope engineer can plan with.
inline constexpr double kSpreadAgreement = 0.02;

// The time step a strength-reduction trial of the scene runs on: the smallest of its last
// stage's (control's when it has no stages), which the consolidation ends with.
double trial_time_step(const Scene& scene);

// The scene with the setting applied: control's time steps and every stage's (a stage
// carries its own copy, and the trials take the last stage's), and the penalty.
Scene with_spread_setting(Scene scene, const SpreadSetting& setting);

// The search's factor at one setting.
struct SpreadFactor {
  std::string setting;  // SpreadSetting::name
  double time_step_scale = 1.0;
  double penalty_scale = 1.0;
  double penalty = 0.0;    // N/m, as run
  double time_step = 0.0;  // s, the smallest time step of the consolidation's last stage
  bool found = false;
  double factor = 0.0;     // the bracket's midpoint, when found
  double last_stable = 0.0, first_failing = 0.0;
  std::string message;     // why none was found (or the consolidation's failure)
  int trials = 0;
  double wall_time_s = 0.0;  // consolidation and search
  bool interrupted = false;
};

// Consolidates `scene` at the setting and runs the search with `settings` as the user gave
// them (the automatic ones resolved afresh, as a run at that setting would). `on_trial` is
// called once per finished trial; `stop` ends it early, interrupted.
SpreadFactor factor_at_setting(const Scene& scene, const SpreadSetting& setting,
                               double consolidation_factor, const FosSettings& settings,
                               const std::function<void(const TrialResult&)>& on_trial,
                               const StopQuery& stop);

struct SettingsSpread {
  bool computed = false;
  std::vector<SpreadFactor> factors;  // in the order of kSpreadSettings
  double spread = 0.0;     // (max - min) / mean of the search's factor and those found
  // How well the spread is known: the widest bracket of those factors over their mean. Each
  // factor is its bracket's midpoint and the slope's threshold may lie anywhere in the
  // bracket, so two midpoints differ from the two thresholds' difference by up to this.
  double resolution = 0.0;
  bool within = false;     // every setting found a factor and the spread <= kSpreadAgreement
  std::string text;        // one sentence for the report
};

// The search's own factor (and its bracket's width) beside the settings' factors.
SettingsSpread judge_spread(double factor_of_safety, double bracket_width,
                            std::vector<SpreadFactor> factors);

}  // namespace dda
