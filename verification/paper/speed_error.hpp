// Speed against error, over a sweep of time steps, one curve per treatment:
// (a) a freely spinning block: area drift after a fixed time against wall time;
// (b) a rigid pendulum: period and amplitude error against the CVODE reference
//     (verification/reference/pendulum_reference.hpp) against wall time;
// and, beyond rotation (speed_closed_form.hpp), a block sliding down an incline and a
// Mohr-Coulomb specimen compressed through its contacts, against their closed forms.
#pragma once

#include <string>
#include <vector>

#include "options.hpp"
#include "speed_closed_form.hpp"
#include "treatments.hpp"

namespace dda::paper {

struct SpinPoint {
  std::string treatment;
  double dt = 0.0;
  int steps = 0;
  RunResult result;     // wall_s: the fastest of the repetitions
  double area_rel_error = 0.0;  // |A - A0| / A0 at the end
};

struct PendulumPoint {
  std::string treatment;
  double dt = 0.0;
  int steps = 0;
  RunResult result;
  double period = 0.0, period_ref = 0.0;        // s
  double amplitude = 0.0, amplitude_ref = 0.0;  // rad, at the last turning point
  int crossings = 0;                            // zero crossings of omega found
};

// The reference the pendulum is judged against: a function of the block and pin, so that
// another reference can be plugged in.
struct PendulumReference {
  double period = 0.0;         // s
  double amplitude = 0.0;      // rad
  double linear_period = 0.0;  // 2 pi / omega0, the small-amplitude period, for context
  std::string source;
};

struct SpeedResults {
  std::vector<SpinPoint> spin;
  std::vector<PendulumPoint> pendulum;
  PendulumReference reference;
  double spin_omega = 0.0, spin_time = 0.0, pendulum_time = 0.0;
  ClosedFormSpeed closed_form;  // the incline and the plastic specimen
};

SpeedResults run_speed(const Options& opt);
void write_speed_csv(const Options& opt, const SpeedResults& r);
std::string speed_report(const Options& opt, const SpeedResults& r);

}  // namespace dda::paper
