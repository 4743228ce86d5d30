#include "solver/schedule.hpp"

#include <algorithm>
#include <cassert>

namespace dda {

double shortest_time_step(const std::vector<double>& time_steps) {
  assert(!time_steps.empty());
  return *std::min_element(time_steps.begin(), time_steps.end());
}

bool reached_time(double t, double end, const std::vector<double>& time_steps) {
  return t >= end - kTimeRoundOff * shortest_time_step(time_steps);
}

}  // namespace dda
