// The report of `dda fos --target-factor F` (studies/bolt_force_search.hpp): DIR/bolt_force.json,
// written whole (docs/factor-of-safety.md, "The bolt force for a target factor").
#pragma once

#include <string>

#include "studies/bolt_force_search.hpp"

namespace dda {

// Throws std::runtime_error naming the file when it cannot be written.
void write_bolt_force_report(const std::string& out_dir, const std::string& scene_path,
                             const BoltForceSearch& search, double wall_time_s);

}  // namespace dda
