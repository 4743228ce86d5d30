// Base shaking: the fixed blocks, the ground, move with a prescribed acceleration
// history, as earthquake loading. The step is solved in the ground's frame: there the free
// blocks feel gravity minus the ground's acceleration (d'Alembert), and every position,
// displacement and velocity the run writes is relative to the ground. For a ground that
// translates as one rigid body this is exact (Newmark 1965 writes the sliding block's motion
// the same way).
#pragma once

#include <optional>
#include <vector>

#include "kinematics/types.hpp"

namespace dda {

struct BaseMotion {
  // Run time (s) at which the history's time 0 is (e.g. the end of a consolidation stage).
  double start = 0.0;
  // Either a sine, a(t) = amplitude sin(2 pi frequency (t - start)) while 0 <= t - start <=
  // cycles / frequency (no cycles: without end), zero before and after ...
  bool is_sine = true;
  Vec2 amplitude = Vec2::Zero();  // m/s^2
  double frequency = 1.0;         // Hz, > 0
  std::optional<double> cycles;   // > 0
  // ... or a record: accelerations (m/s^2, already scaled) at times (s, increasing, from the
  // history's 0), linear between them, zero outside.
  std::vector<double> times;
  std::vector<Vec2> accelerations;
};

// The ground's acceleration at run time t (m/s^2).
Vec2 base_acceleration(const BaseMotion& m, double t);

// Its mean over the run-time interval [t0, t1] (t1 > t0), exact for the sine and for the
// piecewise-linear record: the step's constant body force (the step's inertia is integrated
// with a constant acceleration over the step, Shi 1988).
Vec2 mean_base_acceleration(const BaseMotion& m, double t0, double t1);

}  // namespace dda
