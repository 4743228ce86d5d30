#include "app/plot_command.hpp"

#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "io/input_error.hpp"

namespace dda {
namespace {

namespace fs = std::filesystem;

fs::path plot_dir(const std::string& run_dir, const std::string& out_dir) {
  return out_dir.empty() ? fs::path(run_dir) / "plot" : fs::path(out_dir);
}

void list(const std::vector<fs::path>& written) {
  std::cerr << "dda: pictures:";
  for (const fs::path& p : written) std::cerr << " " << p.string();
  std::cerr << "\n";
}

}  // namespace

int plot_command(const std::string& run_dir, const PlotCommandOptions& options) {
  if (run_dir.empty()) throw InputError("plot: no run directory given (dda plot DIR, DIR as given to dda run --out)");
  std::error_code ec;
  if (!fs::is_directory(run_dir, ec)) throw InputError("plot: " + run_dir + " is not a directory");
  if (!fs::exists(fs::path(run_dir) / "blocks.pvd", ec))
    throw InputError("plot: " + run_dir + " holds no blocks.pvd: not the output directory of dda run");
  PlotOptions plot = options.plot;
  try {
    plot.field = plot_field_from_name(options.field);
    if (plot.exaggeration && !(*plot.exaggeration > 0.0))
      throw std::invalid_argument("plot: --exaggeration must be positive");
    if (plot.width_px < 400 || plot.width_px > 8000)
      throw std::invalid_argument("plot: --width must be 400 to 8000 pixels");
    list(plot_run(run_dir, plot_dir(run_dir, options.out_dir), plot));
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  return 0;
}

void plot_after_run(const std::string& run_dir) {
  try {
    list(plot_run(run_dir, plot_dir(run_dir, ""), PlotOptions{}));
  } catch (const std::exception& e) {
    std::cerr << "dda: warning: no pictures of the run: " << e.what() << "\n";
  }
}

}  // namespace dda
