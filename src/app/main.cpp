// dda: the command line. Thin: parse arguments, read the scene (io), run (solver), write
// results (io), show progress. Exit codes: 0 done, 1 could not write results,
// 2 bad input (message names the place in the file), 3 the run diverged (results so far kept).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>

#include "app/progress.hpp"
#include "io/output.hpp"
#include "io/scene_reader.hpp"
#include "solver/run.hpp"
#include "solver/step.hpp"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitOutputError = 1;
constexpr int kExitInputError = 2;
constexpr int kExitDiverged = 3;

dda::Scene load_scene(const std::string& path) {
  if (path.empty()) {
    std::cerr << "dda: no scene given; running the " << dda::kDefaultSceneName
              << " (a swinging pinned bar, and an octagon thrown onto a fixed floor; see scenes/default.json)\n";
    return dda::parse_scene_text(dda::default_scene_text(), dda::kDefaultSceneName);
  }
  return dda::read_scene_file(path);
}

double run_length(const dda::Scene& scene) {
  return scene.control.steps ? static_cast<double>(*scene.control.steps) : *scene.control.end_time;
}

int run_command(const std::string& scene_path, const std::string& out_dir) {
  const dda::Scene scene = load_scene(scene_path);
  for (const std::string& warning : scene.warnings) {
    std::cerr << "dda: warning: " << warning << "\n";
  }
  dda::World world = dda::make_world(scene);
  dda::OutputWriter writer(out_dir, scene);
  dda::ProgressBar progress(run_length(scene), scene.control.steps ? "steps" : "s");
  const int every = scene.control.output_every;
  const auto observe = [&](const dda::World& w, const dda::RunStats&) {
    if (w.step % every == 0 || dda::is_finished(w)) writer.record(w);
    progress.update(scene.control.steps ? static_cast<double>(w.step) : w.time);
    return true;
  };
  const dda::RunStats stats = dda::run(world, observe);
  progress.finish();
  if (stats.diverged && world.step % every != 0) writer.record(world);  // keep the last state
  writer.finish(world, stats);
  if (stats.diverged) {
    std::cerr << "dda: error: the run diverged at " << stats.message
              << "; results up to there are in " << out_dir << "\n";
    return kExitDiverged;
  }
  std::cerr << "dda: " << stats.steps << " steps (" << stats.cut_steps << " cut) in "
            << stats.wall_time_s << " s; results in " << out_dir << "\n";
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dda: two-dimensional Discontinuous Deformation Analysis"};
  app.require_subcommand(1);
  std::string scene_path;
  std::string out_dir = "dda-out";
  CLI::App* run = app.add_subcommand("run", "Run a scene (the built-in default scene if none is given)");
  run->add_option("scene", scene_path, "Scene file (JSON, see docs/scene-format.md)");
  run->add_option("--out", out_dir, "Directory for summary.json, history.csv and VTK files")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    if (run->parsed()) return run_command(scene_path, out_dir);
  } catch (const dda::InputError& e) {
    std::cerr << "dda: error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "dda: error: " << e.what() << "\n";
    return kExitOutputError;
  }
  return kExitOk;
}
