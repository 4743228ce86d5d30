// report.md: the header (what was run, how to rerun it, which files hold what), the
// treatments' availability, then the sections written by each case.
#pragma once

#include <string>
#include <vector>

#include "falling_octagon.hpp"
#include "options.hpp"
#include "rotation_stress.hpp"
#include "speed_error.hpp"
#include "swinging_octagon.hpp"

namespace dda::paper {

struct AllResults {
  std::vector<FallingRun> falling;
  std::vector<SwingRun> swinging;
  SpeedResults speed;
  RotationStudy rotation;
  double wall_s = 0.0;  // the whole program
};

std::string full_report(const Options& opt, const AllResults& r);

}  // namespace dda::paper
