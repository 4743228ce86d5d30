// dda: the command line. Thin: parse arguments, read the scene (io), run (solver), write
// results (io), show progress. Exit codes: 0 done, 1 could not write results,
// 2 bad input (message names the place in the file), 3 the run diverged (results so far kept).
// `dda cut` cuts a model into a scene (exit codes as for run: 2 bad model, 1 unwritable scene).
// `dda material-point` does the same for one material point on a strain/stress path
// (materials), with 3 for a path that could not be followed. A command line CLI11 cannot
// parse is bad input too (2, the bad argument named); --help and --version exit 0.
#include <CLI/CLI.hpp>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>

#include "app/cut_command.hpp"
#include "app/plot_command.hpp"
#include "app/fos_command.hpp"
#include "app/interrupt.hpp"
#include "app/progress.hpp"
#include "app/ranks.hpp"
#include "app/run_checkpoints.hpp"
#include "app/sweep_command.hpp"
#include "io/checkpoint.hpp"
#include "io/json_input.hpp"
#include "io/material_point_output.hpp"
#include "io/material_point_reader.hpp"
#include "io/output.hpp"
#include "io/scene_reader.hpp"
#include "solver/energy.hpp"
#include "solver/run.hpp"
#include "solver/step.hpp"
#include "studies/strength_reduction.hpp"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitOutputError = 1;
constexpr int kExitInputError = 2;
constexpr int kExitDiverged = 3;

constexpr const char* kSubcommands = "run, material-point, fos, cut, sweep";

// An output path the user gave as "" would write into the current directory (or nowhere):
// refused like any bad input, naming the option.
void require_output_path(const std::string& path, std::string_view command) {
  if (path.empty()) {
    throw dda::InputError(std::string(command) +
                          ": --out is empty; give a directory or file name");
  }
}

// What a command line that CLI11 refused gets: one line naming the bad argument, exit 2
// (CLI11's own codes, 106 to 114, are not the program's). `first` is argv[1] if any.
// A number on the command line: finite, and within [lo, hi] or positive. CLI11's Range
// passes "nan" (every comparison with it is false) and PositiveNumber passes "inf":
// `dda fos --max-factor nan --method limit-analysis` ran for ever, deaf to SIGTERM.
CLI::Validator finite_number(std::string name, std::function<std::string(double)> check) {
  return CLI::Validator(
      [check = std::move(check)](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return text + " is not a number";
        if (!std::isfinite(v)) return text + " is not a finite number";
        return check(v);
      },
      std::move(name));
}

CLI::Validator finite_range(double lo, double hi) {
  std::ostringstream name;
  name << "FLOAT in [" << lo << " - " << hi << "]";
  return finite_number(name.str(), [lo, hi](double v) -> std::string {
    if (v >= lo && v <= hi) return {};
    std::ostringstream why;
    why << "Value " << v << " not in range " << lo << " to " << hi;
    return why.str();
  });
}

CLI::Validator finite_positive() {
  return finite_number("POSITIVE", [](double v) -> std::string {
    if (v > 0.0) return {};
    std::ostringstream why;
    why << "Value " << v << " is not positive";
    return why.str();
  });
}

int report_parse_error(const CLI::ParseError& e, const CLI::App& app, const char* first) {
  std::string message;
  if (first == nullptr) {
    message = "no command given; use one of " + std::string(kSubcommands) + " (dda --help)";
  } else if (first[0] != '-' && app.get_subcommands([&](const CLI::App* sub) {
                                   return sub->get_name() == first;
                                 }).empty()) {
    message = "unknown command '" + std::string(first) + "'; use one of " + kSubcommands +
              " (dda --help)";
  } else {
    message = std::string(e.what()) + " (dda --help, or dda COMMAND --help, lists the options)";
  }
  std::cerr << "dda: error: " << message << "\n";
  return kExitInputError;
}

// The scene and the text it was read from (a checkpoint stores the text).
dda::Scene load_scene(const std::string& path, std::string& text) {
  if (path.empty()) {
    std::cerr << "dda: no scene given; running the " << dda::kDefaultSceneName
              << " (a swinging pinned bar, and an octagon thrown onto a fixed floor; see scenes/default.json)\n";
    text = dda::default_scene_text();
    return dda::parse_scene_text(text, dda::kDefaultSceneName);
  }
  text = dda::input::read_input_file(path, "a scene file");
  return dda::parse_scene_text(text, path);
}

// dda run's checkpoint options: --checkpoint-every N (0: none on the way) and --restart FILE.
struct CheckpointOptions {
  int every = 0;
  std::string restart;
};

// `vtk_format`: "binary" or "ascii" from --vtk-format, or empty for the scene's own;
// `pictures`: draw the run's pictures into OUT/plot at the end.
int run_command(const std::string& scene_path, const std::string& out_dir,
                const std::string& vtk_format, bool pictures, const CheckpointOptions& checkpoints) {
  std::string scene_text;
  std::optional<dda::Checkpoint> resumed;
  if (!checkpoints.restart.empty()) {
    if (!scene_path.empty()) {
      throw dda::InputError("run: --restart continues the scene stored in " + checkpoints.restart +
                            "; give no scene file with it");
    }
    resumed.emplace(dda::read_checkpoint(checkpoints.restart));
    scene_text = resumed->scene_text;
  }
  dda::Scene scene = resumed ? resumed->scene : load_scene(scene_path, scene_text);
  if (!vtk_format.empty()) scene.control.vtk_binary = vtk_format == "binary";
  if (!resumed) {
    for (const std::string& warning : scene.warnings) {
      std::cerr << "dda: warning: " << warning << "\n";
    }
  }
  dda::World world = resumed ? std::move(resumed->world) : dda::make_world(scene);
  std::optional<dda::OutputWriter> output;
  if (resumed) {
    output.emplace(out_dir, scene, resumed->output);
  } else {
    output.emplace(out_dir, scene);
  }
  dda::OutputWriter& writer = *output;
  // The counts go on from the checkpoint's; how that run ended is not this one's. The run
  // loop times this process's part: the earlier part's time is added to it.
  dda::RunStats stats;
  double earlier_wall_time = 0.0;
  if (resumed) {
    stats = resumed->stats;
    stats.interrupted = stats.diverged = false;
    stats.message.clear();
    earlier_wall_time = stats.wall_time_s;
  }
  // The step loop's workspace, and with a restart the kept factor the stopped run had: the
  // continued run then takes its steps as the unbroken run would have, bit for bit.
  dda::StepWorkspace workspace;
  if (resumed && resumed->workspace && !dda::restore_workspace(workspace, *resumed->workspace)) {
    std::cerr << "dda: warning: the linear solver's kept factor in " << checkpoints.restart
              << " could not be rebuilt; the run continues with a new one and agrees with the "
                 "unbroken run to the solver's tolerance, not bit for bit\n";
  }
  dda::RunCheckpoints saved(std::filesystem::path(out_dir) / dda::kRunCheckpointName,
                            checkpoints.every, scene_text, scene, earlier_wall_time, workspace);
  dda::ProgressBar progress(dda::run_length(scene), dda::run_unit(scene));
  const auto observe = [&](const dda::World& w, const dda::RunStats& s) {
    writer.record_if_due(w);
    if (w.step > 0) saved.after_step(w, s, writer.progress());
    progress.update(dda::run_position(scene, w));
    return dda::interrupt_signal() == 0;  // stop after this step, keeping what was written
  };
  // A restarted run's first state was recorded by the run it continues.
  const auto at_start = [&](const dda::World& w, const dda::RunStats& s) {
    return resumed ? dda::interrupt_signal() == 0 : observe(w, s);
  };
  dda::run(world, workspace, dda::RunHook{at_start, {}, observe}, stats);
  progress.finish();
  if (stats.interrupted) {
    stats.message = "interrupted (signal " + std::to_string(dda::interrupt_signal()) +
                    ") after step " + std::to_string(world.step);
  }
  bool checkpoint_left = false;
  if (stats.interrupted || stats.diverged) {
    // Before the last state below is recorded: the checkpoint's output ends where the run
    // in one piece would have had it.
    // A checkpoint that cannot be written costs the restart, not the results: said, and the
    // summary is still written.
    try {
      checkpoint_left = saved.at_stop(world, stats, writer.progress(), stats.diverged);
    } catch (const std::exception& e) {
      std::cerr << "dda: warning: no checkpoint left: " << e.what() << "\n";
    }
  }
  if (stats.diverged || stats.interrupted) writer.record_last(world);
  stats.wall_time_s += earlier_wall_time;  // after the checkpoint, which adds it itself
  writer.finish(world, stats);
  if (stats.interrupted) {
    std::cerr << "dda: " << stats.message << " at t = " << world.time << " s; results up to there are in "
              << out_dir << " (summary.json: \"interrupted\": true)";
    if (checkpoint_left) std::cerr << "; continue with dda run --restart " << saved.file().string();
    std::cerr << "\n";
    return dda::interrupted_exit_code();
  }
  if (stats.diverged) {
    std::cerr << "dda: error: the run diverged at " << stats.message
              << "; results up to there are in " << out_dir;
    if (checkpoint_left) std::cerr << " (the last completed step's state in " << saved.file().string() << ")";
    std::cerr << "\n";
    return kExitDiverged;
  }
  std::cerr << "dda: " << stats.steps << " steps (" << stats.cut_steps << " cut) in "
            << stats.wall_time_s << " s; results in " << out_dir << "\n";
  if (pictures) dda::plot_after_run(out_dir);
  const dda::EnergyLedger& led = world.energy;
  if (dda::energy_lost_beyond(led, world.control.energy_tolerance)) {
    std::cerr << "dda: warning: the energy account lost " << -led.remainder_min
              << " J/m that no term books (" << -100.0 * led.remainder_min / led.scale
              << " % of the energy scale, beyond control.energy_tolerance "
              << world.control.energy_tolerance << "), most at step " << led.remainder_min_step
              << " (summary.json energy.losses_beyond_tolerance; control.energy_losses \"stop\" "
                 "stops such a run)\n";
  }
  return kExitOk;
}

int material_point_command(const std::string& spec_path, const std::string& out_file) {
  if (spec_path.empty()) {
    // There is no built-in default spec; said here rather than by CLI11 so that it is an
    // input error (exit code 2) like every other.
    throw dda::InputError(
        "material-point: no spec file given (dda material-point SPEC.json --out FILE.csv; "
        "see docs/material-point-format.md)");
  }
  const dda::MaterialPointSpec spec = dda::read_material_point_file(spec_path);
  dda::MaterialPointCsv csv(out_file);  // before the run: an unwritable path fails early
  double total = 0.0;
  for (const dda::PathSegment& segment : spec.path) total += segment.steps;
  dda::ProgressBar progress(total, "increments");
  // Rows are written as they come (none kept); flushed every so many so that a run stopped
  // any way but by a signal still keeps nearly all of them, and at the end.
  constexpr int kFlushEvery = 4096;
  const dda::MaterialPointOutcome result = dda::run_material_point(
      spec.parameters(), spec.initial_stress, spec.path, [&](const dda::MaterialPointRow& row) {
        csv.write_row(row);
        if (row.step % kFlushEvery == 0) csv.flush();
        progress.update(row.step);
        return dda::interrupt_signal() == 0;
      });
  csv.flush();
  progress.finish();
  const int increments = result.increments;
  if (result.stopped) {
    std::cerr << "dda: material point interrupted (signal " << dda::interrupt_signal()
              << ") after increment " << increments << "; the rows up to there are in "
              << out_file << "\n";
    return dda::interrupted_exit_code();
  }
  if (!result.ok) {
    std::cerr << "dda: error: " << spec_path << ": the path stopped at " << result.message
              << "; the " << increments << " increments before it are in " << out_file << "\n";
    return kExitDiverged;
  }
  std::cerr << "dda: material point: " << increments << " increments; results in " << out_file
            << "\n";
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) would end the program by SIGXFSZ at the write that passes
  // it, without a word and with a file cut mid-row. Ignored, that write fails with EFBIG,
  // which the output code reports as a file it cannot write (exit 1), keeping only whole
  // files and whole rows (io/output_file.hpp).
  std::signal(SIGXFSZ, SIG_IGN);
  // Likewise a FIFO (or pipe) whose reader has gone: SIGPIPE would end the program without a
  // word; ignored, the write fails with EPIPE and is reported as a file it cannot write.
  std::signal(SIGPIPE, SIG_IGN);
  // SIGINT and SIGTERM from the first moment: one arriving while the input is read or a
  // cut is made is then seen by the command, which stops at its next step, increment or
  // stage with a message, instead of the program vanishing without a word.
  dda::watch_for_interrupts();
  // Under mpirun: the ranks for the life of main (one process otherwise; app/ranks.hpp).
  dda::RankSession ranks(argc, argv);
  CLI::App app{"dda: two-dimensional Discontinuous Deformation Analysis"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("dda ") + DDA_VERSION);
  std::string scene_path;
  std::string out_dir = "dda-out";
  CLI::App* run = app.add_subcommand("run", "Run a scene (the built-in default scene if none is given)");
  run->add_option("scene", scene_path, "Scene file (JSON, see docs/scene-format.md)");
  run->add_option("--out", out_dir, "Directory for summary.json, history.csv and VTK files")
      ->capture_default_str();
  std::string vtk_format;  // empty: the scene's control.vtk_format
  run->add_option("--vtk-format", vtk_format,
                  "How the VTK frames store their arrays: binary (zlib-compressed, appended) or "
                  "ascii; overrides the scene's control.vtk_format")
      ->check(CLI::IsMember({"binary", "ascii"}));
  bool no_picture = false;
  run->add_flag("--no-picture", no_picture, "Draw no pictures into DIR/plot at the end (dda plot draws them later)");
  CheckpointOptions checkpoints;
  run->add_option("--checkpoint-every", checkpoints.every,
                  "Write the run's state to DIR/checkpoint.ddack every N steps (docs/checkpoint.md)")
      ->check(CLI::Range(1, std::numeric_limits<int>::max()));
  run->add_option("--restart", checkpoints.restart,
                  "Continue the run stored in this checkpoint (no scene file with it; --out "
                  "defaults to the checkpoint's directory)");

  std::string plot_run_dir;
  dda::PlotCommandOptions plot_options;
  double plot_exaggeration = 0.0;
  CLI::App* plot = app.add_subcommand("plot", "Pictures of a run from its output directory (blocks, joint states, "
                                              "force chains, energy, monitors)");
  plot->add_option("dir", plot_run_dir, "The run's output directory (dda run --out)");
  plot->add_option("--out", plot_options.out_dir, "Directory for the pictures [DIR/plot]");
  plot->add_option("--time", plot_options.plot.times,
                   "Draw the last frame at or before this time (s); may be given several times [the last frame]");
  plot->add_option("--field", plot_options.field,
                   "Colour blocks by displacement, velocity, stress, plastic-strain or material")
      ->capture_default_str();
  CLI::Option* exaggeration_option = plot->add_option(
      "--exaggeration", plot_exaggeration, "Draw displacements times this [automatic: 1, or larger when they are small]");
  plot->add_option("--width", plot_options.plot.width_px, "Picture width in pixels")->capture_default_str();

  std::string spec_path;
  std::string csv_file = "material-point.csv";
  CLI::App* point = app.add_subcommand(
      "material-point", "Drive one material point along a strain/stress path (CSV out)");
  point->add_option("spec", spec_path, "Spec file (JSON, see docs/material-point-format.md)");
  point->add_option("--out", csv_file, "CSV file: step,exx,eyy,gxy,sxx,syy,szz,sxy,eps_p,branch")
      ->capture_default_str();
  std::string fos_scene;
  std::string fos_dir = "dda-fos";
  dda::FosSettings fos;
  dda::FosCommandOptions fos_options;
  CLI::App* fos_app = app.add_subcommand(
      "fos", "Factor of safety by strength reduction (docs/factor-of-safety.md)");
  fos_app->add_option("scene", fos_scene, "Scene file (JSON, see docs/scene-format.md)");
  fos_app->add_option("--out", fos_dir, "Directory for report.json and report.md")->capture_default_str();
  fos_app->add_option("--tolerance", fos.tolerance, "Width of the final bracket in F")
      ->capture_default_str()->check(finite_range(1e-6, 1.0));
  fos_app->add_option("--min-factor", fos.min_factor, "Lowest F tried")->capture_default_str()
      ->check(finite_range(1e-3, 1.0));
  fos_app->add_option("--max-factor", fos.max_factor, "Highest F tried")->capture_default_str()
      ->check(finite_range(1.0, 1e3));
  fos_app->add_option("--failure-displacement", fos.failure_displacement,
                      "A trial fails when a watched point moves more (m); default: 0.05 x "
                      "sqrt(median free-block area)")->check(finite_positive());
  fos_app->add_option("--trial-time", fos.trial_time,
                      "Simulated time of a trial (s); default: resolves 0.002 g, and at least 20 e-folds "
                      "of the relaxation the consolidation settled at")
      ->check(finite_positive());
  fos_app->add_option("--dynamic-coefficient", fos.dynamic_coefficient,
                      "Velocity carried between the trial's steps (0: static trials, 1: dynamic)")->capture_default_str()
      ->check(finite_range(0.0, 1.0));
  fos_app->add_flag("--reduce-materials", fos.reduce_materials,
                    "Also divide plastic blocks' strengths by F");
  fos_app->add_option("--jobs", fos.jobs, "Trials at once")->capture_default_str()
      ->check(CLI::Range(1, 64));
  fos_app->add_option("--consolidation-factor", fos.consolidation_factor,
                      "Consolidate with the joints' strengths divided by this (e.g. 0.5 for a "
                      "slope whose factor is below 1)")->capture_default_str()
      ->check(finite_range(1e-3, 1.0));
  fos_app->add_option("--method", fos_options.method,
                      "strength-reduction (the search, with the limit analysis beside it) or "
                      "limit-analysis (that alone; docs/limit-analysis.md)")
      ->capture_default_str()
      ->check(CLI::IsMember({"strength-reduction", "limit-analysis"}));
  fos_app->add_flag("--dynamic-check", fos_options.dynamic_check,
                    "After the search, run dynamic trials at 0.95 F and 1.05 F and say whether "
                    "the dynamic factor lies within 5 % of the static one");
  fos_app->add_flag("--spread", fos_options.spread,
                    "After the search, search again with the time steps / 5 and x 5 and the "
                    "penalty / 10 and x 10, and say whether the factor holds within 2 % "
                    "(five times the run)");
  fos_app->add_flag("--skip-limit-analysis", fos_options.skip_limit_analysis,
                    "Run the strength-reduction search without the limit analysis beside it");
  fos_app->add_option("--target-factor", fos_options.target_factor,
                      "Instead of the factor: the force every bolt must hold (pretension = yield "
                      "force) for the slope to stand at this F")
      ->check(finite_range(1e-3, 1e3));
  fos_app->add_option("--samples", fos_options.samples,
                      "Probabilistic factor: draw the scene's random_strengths this many times and "
                      "find each sample's factor (or, with --at-factor, its verdict)")
      ->check(CLI::Range(1L, 1000000L));
  fos_app->add_option("--seed", fos_options.seed,
                      "Seed of the samples' draws (sample k's values depend on seed and k only)")
      ->capture_default_str();
  fos_app->add_option("--at-factor", fos_options.at_factor,
                      "With --samples: one trial per sample at this F (e.g. 1: the probability "
                      "of failure) instead of each sample's search")
      ->check(finite_range(1e-3, 1e3));
  fos_app->add_option("--consolidated", fos_options.consolidated,
                      "Start from the consolidation an earlier dda fos of this scene wrote "
                      "(its OUT/consolidated.ddack) instead of consolidating again");
  fos_app->add_option("--seismic-coefficient", fos.seismic_coefficient,
                      "Pseudo-static horizontal body force, as a share of the weight, along +x "
                      "(negative: along -x)")->capture_default_str()
      ->check(finite_range(-1.0, 1.0));

  std::string model_path;
  std::string scene_out = "scene.json";
  CLI::App* cut = app.add_subcommand(
      "cut", "Cut a model (domain, joint sets) into blocks: a scene for dda run");
  cut->add_option("model", model_path, "Model file (JSON, see docs/model-format.md)");
  cut->add_option("--out", scene_out, "Scene file to write (JSON, see docs/scene-format.md)")
      ->capture_default_str();
  std::string sweep_path;
  std::string sweep_dir = "dda-sweep";
  CLI::App* sweep = app.add_subcommand(
      "sweep", "Run dda fos on variants of a scene (a grid or list of values; docs/sweep.md)");
  sweep->add_option("sweep", sweep_path, "Sweep file (JSON, see docs/sweep.md)");
  sweep->add_option("--out", sweep_dir, "Directory for sweep.csv and each variant's folder")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(e, app, argc > 1 ? argv[1] : nullptr);
  }

  try {
    // A restart without --out continues in the directory its checkpoint is in.
    if (run->parsed() && !checkpoints.restart.empty() && run->get_option("--out")->count() == 0) {
      const std::filesystem::path home = std::filesystem::path(checkpoints.restart).parent_path();
      out_dir = home.empty() ? "." : home.string();
    }
    if (run->parsed()) require_output_path(out_dir, "run");
    if (point->parsed()) require_output_path(csv_file, "material-point");
    if (fos_app->parsed()) require_output_path(fos_dir, "fos");
    if (cut->parsed()) require_output_path(scene_out, "cut");
    if (sweep->parsed()) require_output_path(sweep_dir, "sweep");
    if (run->parsed()) return run_command(scene_path, out_dir, vtk_format, !no_picture, checkpoints);
    if (plot->parsed()) {
      if (exaggeration_option->count() > 0) plot_options.plot.exaggeration = plot_exaggeration;
      return dda::plot_command(plot_run_dir, plot_options);
    }
    if (point->parsed()) return material_point_command(spec_path, csv_file);
    if (fos_app->parsed()) return dda::fos_command(fos_scene, fos_dir, fos, fos_options);
    if (cut->parsed()) return dda::cut_command(model_path, scene_out);
    if (sweep->parsed()) return dda::sweep_command(sweep_path, sweep_dir);
  } catch (const dda::InputError& e) {
    // Every rank reads the same input and stops at the same error: each returns.
    std::cerr << "dda: error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::exception& e) {
    // Perhaps this rank's alone (rank 0's output directory): the others would wait for it.
    std::cerr << "dda: error: " << e.what() << "\n";
    dda::abort_all_ranks(kExitOutputError, std::string("error: ") + e.what());
    return kExitOutputError;
  }
  return kExitOk;
}
