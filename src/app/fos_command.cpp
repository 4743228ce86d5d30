#include "app/fos_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/interrupt.hpp"
#include "app/progress.hpp"
#include "io/block_picture.hpp"
#include "io/fos_report.hpp"
#include "io/scene_reader.hpp"
#include "solver/energy.hpp"
#include "solver/run.hpp"
#include "studies/limit_analysis.hpp"

namespace dda {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitNoFactor = 3;

std::string format(double x, const char* spec) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, x);
  return buf;
}

// The mechanism of one trial: every block coloured by how far its centroid moved from the
// consolidated state (viridis, 0 to the largest), fixed blocks grey.
void write_mechanism_picture(const std::filesystem::path& path, const World& consolidated,
                             const TrialResult& t, const std::string& what) {
  double largest = 0.0;
  std::vector<double> moved(t.world.blocks.size(), 0.0);
  for (std::size_t i = 0; i < moved.size(); ++i) {
    moved[i] = (t.world.blocks[i].moments.centroid - consolidated.blocks[i].moments.centroid).norm();
    largest = std::max(largest, moved[i]);
  }
  std::vector<PictureBlock> blocks;
  for (std::size_t i = 0; i < moved.size(); ++i) {
    const Block& b = t.world.blocks[i];
    const Rgb fill = b.fixed ? Rgb{190, 190, 190}
                             : sequential_colour(largest > 0.0 ? moved[i] / largest : 0.0);
    blocks.push_back({b.vertices, fill});
  }
  PictureOptions options;
  options.width_px = 1600;
  options.title = what + ": F = " + format(t.factor, "%.4f") + ", " +
                  (t.stable ? "stable" : "failing") + " (" + t.verdict + ")";
  options.colour_bar = ColourBar{"displacement since the consolidation (m)", 0.0, largest};
  write_block_picture(path.string(), blocks, options);
}

// The limit analysis's mechanism: every block where the consolidation left it (fixed ones
// grey, free ones pale), then each moving block again, moved rigidly along its mechanism
// velocity (v + omega x (p - c)) so that the fastest moves a quarter of a typical block's
// size, coloured by its speed (viridis).
void write_limit_analysis_picture(const std::filesystem::path& path, const World& world,
                                  const LimitAnalysisResult& la) {
  // (A mechanism has free blocks, so the median exists.)
  if (la.mechanism.empty()) return;
  const double shown = 0.25 * std::sqrt(median_free_block_area(world));
  std::vector<PictureBlock> blocks;
  for (const Block& b : world.blocks) {
    blocks.push_back({b.vertices, b.fixed ? Rgb{190, 190, 190} : Rgb{235, 235, 235}});
  }
  for (auto it = la.mechanism.rbegin(); it != la.mechanism.rend(); ++it) {  // fastest on top
    const Block& b = world.blocks[static_cast<std::size_t>(it->block)];
    Polygon moved = b.vertices;
    for (Vec2& p : moved) {
      const Vec2 r = p - b.moments.centroid;
      p += shown * (it->velocity + it->angular_velocity * Vec2(-r.y(), r.x()));
    }
    blocks.push_back({moved, sequential_colour(it->velocity.norm())});
  }
  PictureOptions options;
  options.width_px = 1600;
  options.title = "limit-analysis mechanism at F = " + format(la.upper, "%.4f") +
                  " (rigid motion exaggerated: the fastest block moved " + format(shown, "%.3g") +
                  " m)";
  options.colour_bar = ColourBar{"speed, share of the fastest block's", 0.0, 1.0};
  write_block_picture(path.string(), blocks, options);
}

}  // namespace

int fos_command(const std::string& scene_path, const std::string& out_dir, FosSettings settings,
                const std::string& method, bool skip_limit_analysis) {
  if (method != "strength-reduction" && method != "limit-analysis") {
    throw InputError("fos: --method: must be strength-reduction or limit-analysis, got " + method);
  }
  if (skip_limit_analysis && method == "limit-analysis") {
    throw InputError("fos: --skip-limit-analysis with --method limit-analysis leaves nothing to do");
  }
  if (scene_path.empty()) {
    throw InputError(
        "fos: no scene given (dda fos SCENE.json --out DIR; see docs/factor-of-safety.md)");
  }
  const Scene scene = with_seismic_coefficient(read_scene_file(scene_path), settings.seismic_coefficient);
  for (const std::string& warning : scene.warnings) std::cerr << "dda: warning: " << warning << "\n";
  bool any_free = false;
  for (const BlockSpec& b : scene.blocks) any_free = any_free || !b.fixed;
  if (!any_free) throw InputError(scene_path + ": blocks: every block is fixed; nothing can fail");

  std::cerr << "dda: consolidating " << scene_path << " at F = " << settings.consolidation_factor << "\n";
  // SIGINT or SIGTERM: the consolidation or the running trials stop at their next step, and
  // the report holds the trials judged so far (a second signal ends the program at once).
  watch_for_interrupts();
  const auto interrupted = [] { return interrupt_signal() != 0; };
  ProgressBar progress(run_length(scene), run_unit(scene));
  const Consolidation consolidation =
      consolidate(scene, settings.consolidation_factor, [&](const World& w, const RunStats&) {
        progress.update(run_position(scene, w));
        return !interrupted();
      });
  progress.finish();
  if (consolidation.stats.diverged) {
    std::cerr << "dda: error: the consolidation diverged at " << consolidation.stats.message
              << "; no trial was run\n";
    return kExitNoFactor;
  }
  const World& world = consolidation.world;
  const ConsolidationInfo info{consolidation.stats.steps, world.time,
                               consolidation.stats.wall_time_s, scene_energy(world).kinetic,
                               consolidation.stats.bonds_broken, consolidation.stats.broken_bonds};
  settings = resolve_fos_settings(world, settings);
  const auto stop_message = [&](const std::string& when) {
    return "interrupted (signal " + std::to_string(interrupt_signal()) + ") " + when;
  };
  if (consolidation.stats.interrupted) {
    FosResult none;
    none.interrupted = true;
    none.message = stop_message("during the consolidation, at t = " + format(world.time, "%g") +
                                " s; no trial was run");
    write_fos_report(out_dir, scene, settings, info, none, consolidation.stats.wall_time_s);
    std::cerr << "dda: " << none.message << "; report in " << out_dir << "\n";
    return interrupted_exit_code();
  }
  std::cerr << "dda: the consolidation broke " << info.bonds_broken << " bonds\n";

  // The second factor, from the same consolidated blocks: rigid-block limit analysis, and
  // each free block's own bound.
  LimitAnalysisInfo limit;
  limit.method = method;
  LimitAnalysisSettings la_settings;
  la_settings.min_factor = settings.min_factor;
  la_settings.max_factor = settings.max_factor;
  // Beside the search, whose bracket is 0.01 wide, a bracket of 0.5 % of the factor: 9
  // programs instead of the 13 of 1e-3 (each takes seconds to tens of seconds at 2000
  // blocks; docs/limit-analysis.md).
  la_settings.relative_tolerance = method == "limit-analysis" ? 1e-3 : 5e-3;
  if (skip_limit_analysis) {
    limit.analysis.reason = "skipped (--skip-limit-analysis)";
  } else {
    // The single-block bounds first: the smallest caps the slope's search (often at once).
    limit.single_block_bounds = single_block_bounds(world, la_settings);
    LimitAnalysisSettings capped = la_settings;
    if (!limit.single_block_bounds.empty()) {
      capped.known_inadmissible = limit.single_block_bounds.front().upper;
    }
    limit.analysis = limit_analysis(world, capped);
  }
  std::cerr << "dda: " << limit_analysis_line(limit) << "\n";
  const auto draw_limit_analysis = [&] {
    write_limit_analysis_picture(std::filesystem::path(out_dir) / "limit_analysis.png", world,
                                 limit.analysis);
  };
  if (method == "limit-analysis") {
    FosResult none;
    none.message = "strength reduction not run (--method limit-analysis)";
    write_fos_report(out_dir, scene, settings, info, none,
                     consolidation.stats.wall_time_s + limit.analysis.wall_time_s, &limit);
    draw_limit_analysis();
    std::cerr << "dda: report in " << out_dir << "\n";
    return limit.analysis.found ? kExitOk : kExitNoFactor;
  }
  std::cerr << "dda: trials of " << settings.trial_time << " s, failing beyond "
            << settings.failure_displacement << " m, " << settings.jobs << " at once\n";

  const auto start = std::chrono::steady_clock::now();
  const FosResult result = find_factor_of_safety(settings, [&](const std::vector<double>& factors) {
    return run_trials(
        world, settings, factors,
        [](const TrialResult& t) { std::cerr << "dda: " << trial_line(t) << "\n"; }, interrupted);
  });
  const double wall = consolidation.stats.wall_time_s +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (result.interrupted) {
    FosResult kept = result;
    kept.message = stop_message(result.message);
    write_fos_report(out_dir, scene, settings, info, kept, wall, &limit);
    std::cerr << "dda: " << kept.message << "; report of the trials so far in " << out_dir
              << " (report.json: \"interrupted\": true)\n";
    return interrupted_exit_code();
  }
  FosResult reported = result;
  if (result.found) {
    for (const TrialResult& t : result.trials) {
      if (t.factor != result.first_failing || t.interrupted || skip_limit_analysis) continue;
      limit.has_failing = true;
      limit.failing_factor = t.factor;
      limit.failing = trial_mechanism(world, t.world, la_settings);
      std::cerr << "dda: " << failing_mechanism_line(limit) << "\n";
      break;
    }
    // The search's factor beside the bounds it may not exceed (the smallest single-block
    // bound) and the associative limit analysis it should not exceed.
    std::string note;
    if (!limit.single_block_bounds.empty() &&
        result.last_stable > limit.single_block_bounds.front().factor) {
      note = "stable trials above the smallest single-block bound F = " +
             format(limit.single_block_bounds.front().factor, "%.4f") + " (block " +
             std::to_string(limit.single_block_bounds.front().block) +
             "): a trial held a block its own strength cannot hold, so the factor is not "
             "trustworthy";
    } else if (limit.analysis.found && result.last_stable > limit.analysis.upper) {
      note = "stable trials above the limit-analysis factor F = " +
             format(limit.analysis.factor, "%.4f") +
             ", which associative friction makes an upper bound for rigid blocks";
    }
    if (!note.empty()) {
      reported.message += (reported.message.empty() ? "" : "; ") + note;
      std::cerr << "dda: warning: " << note << "\n";
    }
  }
  write_fos_report(out_dir, scene, settings, info, reported, wall, &limit);
  if (!result.found) {
    std::cerr << "dda: error: no factor of safety: " << result.message << "; trials in "
              << out_dir << "/report.json\n";
    return kExitNoFactor;
  }
  draw_limit_analysis();
  for (const TrialResult& t : result.trials) {
    if (t.factor == result.last_stable) {
      write_mechanism_picture(std::filesystem::path(out_dir) / "last_stable.png", world, t,
                              "last stable trial");
    } else if (t.factor == result.first_failing) {
      write_mechanism_picture(std::filesystem::path(out_dir) / "first_failing.png", world, t,
                              "first failing trial");
    }
  }
  std::cerr << "dda: factor of safety " << result.factor_of_safety << " (bracket "
            << result.last_stable << " to " << result.first_failing << ") in " << wall
            << " s; report and pictures in " << out_dir << "\n";
  return kExitOk;
}

}  // namespace dda
