// The scale of a time-step schedule (ControlSettings::time_steps, a stage's own): its
// shortest step, and the share of it within which two times count as one. A run's last
// step is shortened to land on its end (or a stage's), and lands there up to round-off.
#pragma once

#include <vector>

namespace dda {

// Times closer than this share of the schedule's shortest step count as equal.
inline constexpr double kTimeRoundOff = 1e-9;

// The shortest step of a schedule (s). The schedule must not be empty.
double shortest_time_step(const std::vector<double>& time_steps);

// Whether time t (s) has reached `end` (s) up to round-off:
// t >= end - kTimeRoundOff x the schedule's shortest step.
bool reached_time(double t, double end, const std::vector<double>& time_steps);

}  // namespace dda
