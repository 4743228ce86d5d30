#include "app/fos_command.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>

#include "app/fos_ranks.hpp"
#include "app/fos_samples.hpp"
#include "app/interrupt.hpp"
#include "app/progress.hpp"
#include "app/ranks.hpp"
#include "common/printf_text.hpp"
#include "io/bolt_force_report.hpp"
#include "io/checkpoint.hpp"
#include "io/fos_pictures.hpp"
#include "io/fos_report.hpp"
#include "io/json_input.hpp"
#include "io/output_file.hpp"
#include "io/scene_reader.hpp"
#include "solver/energy.hpp"
#include "solver/run.hpp"
#include "solver/sparse_cholesky.hpp"
#include "studies/bolt_force_search.hpp"
#include "studies/factor_cross_check.hpp"
#include "studies/limit_analysis.hpp"
#include "studies/settings_spread.hpp"
#include "studies/speculative_search.hpp"
#include "studies/trial_mechanism.hpp"

namespace dda {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitNoFactor = 3;

// --target-factor F: the bisection on the bolts' force, a trial at F each, the report in
// DIR/bolt_force.json.
int bolt_force_command(const Scene& scene, const std::string& scene_path, const std::string& out_dir,
                       const FosSettings& settings, double target) {
  prepare_output_directory(out_dir, {"bolt_force.json"});
  const auto start = std::chrono::steady_clock::now();
  std::cerr << "dda: the force each of the " << scene.bolts.size()
            << " bolts must hold for F = " << target << ": one trial at F per force tried\n";
  const BoltForceSearch search = find_bolt_force(scene, settings, target, [] { return interrupt_signal() != 0; });
  for (const BoltForceTrial& t : search.trials) {
    std::cerr << "dda: bolts at " << printf_text(t.force, "%.6g") << " N/m: "
              << (t.stable ? "stable" : "failing") << " (" << t.verdict << ")\n";
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_bolt_force_report(out_dir, scene_path, search, wall);
  if (search.interrupted) {
    std::cerr << "dda: interrupted (signal " << interrupt_signal() << "); report in " << out_dir << "\n";
    return interrupted_exit_code();
  }
  if (!search.found) {
    std::cerr << "dda: error: " << (search.message.empty() ? "no bolt force found" : search.message)
              << "; report in " << out_dir << "\n";
    return kExitNoFactor;
  }
  std::cout << "bolt force for F = " << target << ": " << printf_text(search.force, "%.6g")
            << " N/m each bolt (fails at " << printf_text(search.failing_force, "%.6g") << ")\n";
  std::cerr << "dda: report in " << out_dir << "/bolt_force.json\n";
  return kExitOk;
}

}  // namespace

int fos_command(const std::string& scene_path, const std::string& out_dir, FosSettings settings,
                const FosCommandOptions& options) {
  const std::string& method = options.method;
  const bool skip_limit_analysis = options.skip_limit_analysis;
  const bool dynamic_check = options.dynamic_check;
  if (method != "strength-reduction" && method != "limit-analysis") {
    throw InputError("fos: --method: must be strength-reduction or limit-analysis, got " + method);
  }
  if (skip_limit_analysis && method == "limit-analysis") {
    throw InputError("fos: --skip-limit-analysis with --method limit-analysis leaves nothing to do");
  }
  if (dynamic_check && method == "limit-analysis") {
    throw InputError("fos: --dynamic-check checks the strength-reduction search's trials; "
                     "--method limit-analysis runs none");
  }
  if (dynamic_check && settings.dynamic_coefficient >= 1.0) {
    throw InputError("fos: --dynamic-check compares dynamic trials with the search's, which are "
                     "dynamic already (--dynamic-coefficient 1)");
  }
  if (options.spread && method == "limit-analysis") {
    throw InputError("fos: --spread repeats the strength-reduction search at other settings; "
                     "--method limit-analysis runs none");
  }
  if (scene_path.empty()) {
    throw InputError(
        "fos: no scene given (dda fos SCENE.json --out DIR; see docs/factor-of-safety.md)");
  }
  const bool target = options.target_factor > 0.0;
  if (target && (method != "strength-reduction" || dynamic_check || options.spread)) {
    throw InputError("fos: --target-factor searches the bolts' force with trials at one F; it "
                     "runs no search of F, so --method limit-analysis, --dynamic-check and "
                     "--spread do not apply");
  }
  const bool sampled = options.samples > 0;
  if (options.at_factor > 0.0 && !sampled) {
    throw InputError("fos: --at-factor judges each sample of --samples at one F; give --samples N");
  }
  if (sampled && (target || method != "strength-reduction" || dynamic_check || options.spread)) {
    throw InputError("fos: --samples runs trials per sample of the random strengths; "
                     "--target-factor, --method limit-analysis, --dynamic-check and --spread do "
                     "not apply");
  }
  const std::string scene_text = input::read_input_file(scene_path, "a scene file");
  const Scene scene = with_seismic_coefficient(parse_scene_text(scene_text, scene_path),
                                               settings.seismic_coefficient);
  if (sampled && scene.random_strengths.variables.empty()) {
    throw InputError(scene_path + ": random_strengths: --samples draws the strengths this key "
                     "describes, and the scene has none (docs/scene-format.md)");
  }
  if (target) {
    if (scene.bolts.empty()) {
      throw InputError(scene_path + ": bolts: --target-factor finds the force the scene's bolts "
                       "must hold, and the scene has none");
    }
    // Its bisection is one trial after another: rank 0 runs it alone.
    if (!is_root_rank()) return kExitOk;
    return bolt_force_command(scene, scene_path, out_dir, settings, options.target_factor);
  }
  for (const std::string& warning : scene.warnings) std::cerr << "dda: warning: " << warning << "\n";
  bool any_free = false;
  for (const BlockSpec& b : scene.blocks) any_free = any_free || !b.fixed;
  if (!any_free) throw InputError(scene_path + ": blocks: every block is fixed; nothing can fail");
  // The output directory before any work: a search of hours whose report cannot be written
  // fails now, not at its end. Rank 0 alone writes (app/ranks.hpp).
  if (is_root_rank()) {
    prepare_output_directory(out_dir, {"report.json", "report.md", "limit_analysis.png",
                                       "last_stable.png", "first_failing.png", "trials.png",
                                       "limit_analysis_close.png", "last_stable_close.png",
                                       "first_failing_close.png", "factors.png", "verdicts.png",
                                       kConsolidationCheckpointName});
  }

  // SIGINT or SIGTERM (watched from the start of main): the consolidation or the running
  // trials stop at their next step, and the report holds the trials judged so far (a second
  // signal ends the program at once).
  const auto interrupted = [] { return interrupt_signal() != 0; };
  // The consolidation: made here (and kept in OUT/consolidated.ddack for a later dda fos of
  // the same scene), or read from --consolidated (docs/checkpoint.md).
  const ConsolidationSettings made_at{settings.consolidation_factor, settings.seismic_coefficient};
  const bool consolidating = options.consolidated.empty();
  const Consolidation consolidation = [&] {
    if (!consolidating) {
      std::cerr << "dda: the consolidation of " << scene_path << " from " << options.consolidated << "\n";
      return read_consolidation(options.consolidated, scene_text, scene, made_at);
    }
    std::cerr << "dda: consolidating " << scene_path << " at F = " << settings.consolidation_factor << "\n";
    ProgressBar progress(run_length(scene), run_unit(scene));
    Consolidation made =
        consolidate(scene, settings.consolidation_factor, [&](const World& w, const RunStats&) {
          progress.update(run_position(scene, w));
          return !interrupted();
        });
    progress.finish();
    return made;
  }();
  if (consolidation.stats.diverged) {
    std::cerr << "dda: error: the consolidation diverged at " << consolidation.stats.message
              << "; no trial was run\n";
    return kExitNoFactor;
  }
  const World& world = consolidation.world;
  ConsolidationInfo info;
  info.steps = consolidation.stats.steps;
  info.time = world.time;
  info.wall_time_s = consolidation.stats.wall_time_s;
  info.kinetic_end = scene_energy(world).kinetic;
  info.bonds_broken = consolidation.stats.bonds_broken;
  info.broken_bonds = consolidation.stats.broken_bonds;
  info.factor = settings.consolidation_factor;
  info.settling = consolidation.settling;
  // The settings as given, for the searches of --spread (each resolves its own from its
  // consolidation, as a run at that setting would).
  FosSettings given = settings;
  settings = resolve_fos_settings(world, settings, consolidation.settling.relaxation_steps);
  // Under mpirun the search's rounds are --jobs trials per rank wide: the report gives that
  // width, which a run on one process with --jobs that wide matches trial for trial.
  const auto reported_settings = [&settings] {
    FosSettings r = settings;
    r.jobs = settings.jobs * rank_count();
    return r;
  };
  const auto stop_message = [&](const std::string& when) {
    return "interrupted (signal " + std::to_string(interrupt_signal()) + ") " + when;
  };
  if (consolidation.stats.interrupted) {
    FosResult none;
    none.interrupted = true;
    none.message = stop_message("during the consolidation, at t = " + printf_text(world.time, "%g") +
                                " s; no trial was run");
    if (is_root_rank()) {
      write_fos_report(out_dir, scene, reported_settings(), info, none, consolidation.stats.wall_time_s);
    }
    std::cerr << "dda: " << none.message << "; report in " << out_dir << "\n";
    return interrupted_exit_code();
  }
  if (consolidating && is_root_rank()) {
    // An extra for later searches: one that cannot be written does not stop this one.
    try {
      write_file_whole(std::filesystem::path(out_dir) / kConsolidationCheckpointName,
                       encode_consolidation(scene_text, scene, made_at, consolidation));
    } catch (const std::exception& e) {
      std::cerr << "dda: warning: the consolidation is not kept: " << e.what() << "\n";
    }
  }
  std::cerr << "dda: the consolidation broke " << info.bonds_broken << " bonds"
            << settling_phrase(info.settling) << "\n";
  if (info.bonds_broken > 0) {
    info.bond_check = check_consolidation_bonds(scene, settings.consolidation_factor,
                                                consolidation.stats.broken_bonds, interrupted);
    std::cerr << "dda: " << bond_check_line(info.bond_check) << " ("
              << printf_text(info.bond_check.wall_time_s, "%.1f") << " s)\n";
  }

  if (sampled) return fos_samples_command(scene, out_dir, world, settings, info, options);

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
  // The limit analysis's upper end bounds the factor of non-dilating joints from above: the
  // search tries it first instead of F = 2 (FosSettings::first_failing_guess).
  if (limit.analysis.found) {
    settings.first_failing_guess = limit.analysis.upper;
    given.first_failing_guess = limit.analysis.upper;
  }
  const auto draw_limit_analysis = [&] {
    write_limit_analysis_picture(std::filesystem::path(out_dir) / "limit_analysis.png", world,
                                 limit.analysis);
  };
  if (method == "limit-analysis") {
    if (!is_root_rank()) return limit.analysis.found ? kExitOk : kExitNoFactor;
    FosResult none;
    none.message = "strength reduction not run (--method limit-analysis)";
    write_fos_report(out_dir, scene, settings, info, none,
                     consolidation.stats.wall_time_s + limit.analysis.wall_time_s, &limit);
    draw_limit_analysis();
    std::cerr << "dda: report in " << out_dir << "\n";
    return limit.analysis.found ? kExitOk : kExitNoFactor;
  }
  std::cerr << "dda: trials of " << settings.trial_time << " s, failing beyond "
            << settings.failure_displacement << " m, " << settings.jobs << " at once";
  if (rank_count() > 1) {
    std::cerr << " on each of " << rank_count() << " ranks (rounds of "
              << reported_settings().jobs << ")";
  }
  std::cerr
            << (settings.jobs > 1 && blas_calls_serialised()
                    ? " (their BLAS calls one at a time: the BLAS loaded is not known to be safe "
                      "for concurrent callers; docs/factor-of-safety.md, section 3)"
                    : "")
            << "\n";

  const auto start = std::chrono::steady_clock::now();
  const auto print_trial = [](const TrialResult& t) { std::cerr << "dda: " << trial_line(t) << "\n"; };
  FosResult result =
      rank_count() > 1
          ? search_over_ranks(world, settings, print_trial, interrupted)
          : search_on_threads(
                settings,
                [&](double f, const StopQuery& stop) { return run_trial(world, settings, f, stop); },
                print_trial, interrupted);
  // The rest (the pictures, the mechanism, the dynamic check, --spread and the report) is
  // rank 0's. It needs the worlds of the bracket's two trials: those another rank ran are
  // run again here (at most two trials' time; docs/mpi.md).
  if (!is_root_rank()) {
    return result.interrupted ? interrupted_exit_code() : result.found ? kExitOk : kExitNoFactor;
  }
  if (result.found && !result.interrupted) {
    const int again = trial_worlds_on_root(result, world, settings,
                                           {result.last_stable, result.first_failing}, interrupted);
    if (again > 0) {
      std::cerr << "dda: ran " << again << " trial" << (again > 1 ? "s" : "")
                << " of the bracket again on rank 0 for its pictures\n";
    }
  }
  const double wall = consolidation.stats.wall_time_s +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (result.interrupted) {
    FosResult kept = result;
    kept.message = stop_message(result.message);
    write_fos_report(out_dir, scene, reported_settings(), info, kept, wall, &limit);
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
      std::cerr << "dda: " << failing_mechanism_line(limit, scene) << "\n";
      break;
    }
    // The search's factor beside the bounds it may not exceed (the smallest single-block
    // bound) and the associative limit analysis it should not exceed, or lie far below
    // without a reason given.
    const FactorCrossCheck check =
        cross_check_factor(result, limit.single_block_bounds, limit.analysis);
    if (!check.text.empty()) {
      reported.message += (reported.message.empty() ? "" : "; ") + check.text;
      std::cerr << "dda: " << (check.warning ? "warning: " : "note: ") << check.text << "\n";
    }
  }
  // Dynamic trials just below and above the factor, run after the search (two at once with
  // two jobs).
  std::optional<DynamicCheck> dynamic;
  if (dynamic_check && result.found) {
    FosSettings dyn = settings;
    dyn.dynamic_coefficient = 1.0;
    std::cerr << "dda: dynamic trials at F x (1 -+ " << kDynamicAgreement << ")\n";
    dynamic = judge_dynamic_check(
        result, run_trials(world, dyn, dynamic_check_factors(result.factor_of_safety),
                           [](const TrialResult& t) { std::cerr << "dda: dynamic " << trial_line(t) << "\n"; },
                           interrupted));
    if (interrupted()) {
      dynamic->agrees = false;
      dynamic->text = stop_message("during the dynamic check; the search's factor stands");
    }
    std::cerr << "dda: " << (dynamic->agrees ? "" : "note: ") << dynamic->text << "\n";
  }
  // The search again at each of kSpreadSettings, one after another (each with its trials
  // `jobs` at once).
  std::optional<SettingsSpread> spread;
  if (options.spread && result.found && !interrupted()) {
    std::vector<SpreadFactor> factors;
    for (const SpreadSetting& setting : kSpreadSettings) {
      std::cerr << "dda: the search at " << setting.name << "\n";
      factors.push_back(factor_at_setting(
          scene, setting, settings.consolidation_factor, given,
          [&setting](const TrialResult& t) {
            std::cerr << "dda: " << setting.name << ": " << trial_line(t) << "\n";
          },
          interrupted));
      if (interrupted()) break;
    }
    spread = judge_spread(result.factor_of_safety, result.first_failing - result.last_stable,
                          std::move(factors));
    if (interrupted()) {
      spread->within = false;
      spread->text = stop_message("during the searches at other settings; the search's factor stands");
    }
    std::cerr << "dda: " << (spread->within ? "" : "note: ") << spread->text << "\n";
  }
  write_fos_report(out_dir, scene, reported_settings(), info, reported, wall, &limit,
                   dynamic ? &*dynamic : nullptr, spread ? &*spread : nullptr);
  // The trials' chart also when no factor was found: it shows why (all stable, all failing).
  write_trials_chart(std::filesystem::path(out_dir) / "trials.png", result, settings.failure_displacement,
                     limit.analysis.found ? &limit.analysis : nullptr);
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
  return interrupted() ? interrupted_exit_code() : kExitOk;
}

}  // namespace dda
