#include "app/fos_samples.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>

#include "app/interrupt.hpp"
#include "io/rank_messages.hpp"
#include "app/ranks.hpp"
#include "io/probabilistic_report.hpp"

namespace dda {

int fos_samples_command(const Scene& scene, const std::string& out_dir, const World& consolidated,
                        const FosSettings& settings, const ConsolidationInfo& info,
                        const FosCommandOptions& options) {
  ProbabilisticSettings p;
  p.samples = options.samples;
  p.seed = options.seed;
  p.at_factor = options.at_factor;
  // Under mpirun each rank runs every rank_count()-th sample (a sample's draw depends on the
  // seed and its index alone, so not on the rank that runs it) and rank 0 gathers them.
  p.share = rank_index();
  p.shares = rank_count();
  std::cerr << "dda: " << p.samples << " samples of " << scene.random_strengths.variables.size()
            << " random strengths (seed " << p.seed << "), ";
  if (p.at_factor > 0.0) {
    std::cerr << "one trial each at F = " << p.at_factor;
  } else {
    std::cerr << "each sample's factor by the search";
  }
  std::cerr << ", " << settings.jobs << " at once";
  if (p.shares > 1) std::cerr << " on each of " << p.shares << " ranks";
  std::cerr << "; trials of " << settings.trial_time
            << " s, failing beyond " << settings.failure_displacement << " m\n";
  const auto start = std::chrono::steady_clock::now();
  long finished = 0;
  const long here = (p.samples - p.share + p.shares - 1) / p.shares;  // this rank's share
  ProbabilisticResult result = run_probabilistic(
      consolidated, scene.joint_materials, scene.random_strengths, settings, p,
      [&](const SampleOutcome& o) {
        ++finished;
        std::cerr << "dda: sample " << o.index << " (" << finished << "/" << here << "): "
                  << (o.failing ? "failing" : "stable");
        if (p.at_factor <= 0.0) {
          std::cerr << ", F = ";
          if (o.factor_found) {
            std::cerr << o.factor;
          } else {
            std::cerr << "none";
          }
        }
        std::cerr << " (" << o.trials << " trials, " << o.wall_time_s << " s)\n";
      },
      [] { return interrupt_signal() != 0; });
  if (p.shares > 1) {
    std::vector<SampleOutcome> mine;
    for (long k = p.share; k < p.samples; k += p.shares) {
      mine.push_back(result.samples[static_cast<std::size_t>(k)]);
    }
    const std::vector<std::string> shares = gather_to_root(pack_samples(mine));
    if (!is_root_rank()) return result.interrupted ? interrupted_exit_code() : 0;
    for (std::size_t r = 1; r < shares.size(); ++r) {
      std::vector<SampleOutcome> theirs;
      for (SampleOutcome& o : unpack_samples(shares[r])) {
        if (o.index % p.shares == static_cast<long>(r)) theirs.push_back(std::move(o));
      }
      add_samples(result, std::move(theirs));
    }
  }
  const double wall = info.wall_time_s +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  FosResult none;
  none.interrupted = result.interrupted;
  none.message = "a probabilistic study (--samples): see \"probabilistic\"";
  write_fos_report(out_dir, scene, settings, info, none, wall, nullptr, nullptr, nullptr, &result);
  const std::string chart = write_probabilistic_chart(out_dir, result, scene.random_strengths);
  std::cerr << "dda: " << probabilistic_line(result) << "\n";
  if (result.interrupted) {
    std::cerr << "dda: interrupted (signal " << interrupt_signal() << ") after "
              << result.summary.judged << " of " << p.samples << " samples; report in " << out_dir
              << " (report.json: \"probabilistic\": {\"interrupted\": true})\n";
    return interrupted_exit_code();
  }
  std::cout << probabilistic_line(result) << "\n";
  std::cerr << "dda: report";
  if (!chart.empty()) std::cerr << " and " << chart;
  std::cerr << " in " << out_dir << " (" << wall << " s)\n";
  return 0;
}

}  // namespace dda
