// `dda plot DIR`: the pictures of a run drawn from its output files (io/run_pictures), and
// the same pictures at the end of `dda run` unless --no-picture.
#pragma once

#include <string>

#include "io/run_pictures.hpp"

namespace dda {

// The settings as the command line gives them: a field name, and the output directory
// (empty: DIR/plot).
struct PlotCommandOptions {
  std::string out_dir;
  std::string field = "displacement";
  PlotOptions plot;
};

// Returns the exit code (0); throws InputError for bad options or a directory that is not a
// run's (exit 2) and std::runtime_error when a file cannot be read or written (exit 1).
int plot_command(const std::string& run_dir, const PlotCommandOptions& options);

// After a run: the pictures into RUN_DIR/plot, listed on stderr. A picture that cannot be
// drawn is a warning naming why; the run's results stand.
void plot_after_run(const std::string& run_dir);

}  // namespace dda
