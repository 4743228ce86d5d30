// Per-step settings, rebuilt for every attempt of a step (no globals).
#pragma once

namespace dda {

struct StepContext {
  double dt = 0.0;                    // this attempt's time step (s)
  double penalty = 0.0;               // pin and contact normal stiffness (N/m)
  double dynamic_coefficient = 1.0;   // share of last velocity carried in, [0, 1]
  double allowed_displacement = 0.0;  // max_displacement_ratio * w0 (m)
};

}  // namespace dda
