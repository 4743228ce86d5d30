// `dda fos SCENE --samples N --seed S [--at-factor F]`: after the consolidation of
// fos_command, the probabilistic factor (studies/probabilistic_fos.hpp), its report
// (report.json's "probabilistic" section, report.md) and its histogram.
#pragma once

#include <string>

#include "app/fos_command.hpp"
#include "io/fos_report.hpp"

namespace dda {

// `consolidated` and `settings` as fos_command has them (settings resolved). Returns the
// exit code: 0 when every sample was judged, interrupted_exit_code() when a signal stopped
// it (the report then holds the samples judged so far).
int fos_samples_command(const Scene& scene, const std::string& out_dir, const World& consolidated,
                        const FosSettings& settings, const ConsolidationInfo& info,
                        const FosCommandOptions& options);

}  // namespace dda
