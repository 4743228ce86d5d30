#include "app/fos_ranks.hpp"

#include <string>

#include "app/ranks.hpp"
#include "io/rank_messages.hpp"

namespace dda {

FosResult search_over_ranks(const World& consolidated, const FosSettings& per_rank,
                            const std::function<void(const TrialResult&)>& done,
                            const StopQuery& stop) {
  const auto ranks = static_cast<std::size_t>(rank_count());
  const auto me = static_cast<std::size_t>(rank_index());
  FosSettings wide = per_rank;
  wide.jobs = per_rank.jobs * rank_count();
  return find_factor_of_safety(wide, [&](const std::vector<double>& factors) {
    // Trial k of the round runs on rank k % ranks: a round narrower than the ranks (the
    // search's first) leaves the last ranks idle rather than split a trial.
    std::vector<double> mine;
    for (std::size_t k = me; k < factors.size(); k += ranks) mine.push_back(factors[k]);
    std::vector<TrialResult> ran = run_trials(consolidated, per_rank, mine, {}, stop);
    const std::vector<std::string> all = gather_to_all(pack_trials(ran));
    std::vector<TrialResult> round(factors.size());
    for (std::size_t r = 0; r < ranks; ++r) {
      if (r == me) {
        for (std::size_t j = 0; j < ran.size(); ++j) round[me + j * ranks] = std::move(ran[j]);
        continue;
      }
      std::vector<TrialResult> theirs = unpack_trials(all[r]);
      for (std::size_t j = 0; j < theirs.size() && r + j * ranks < round.size(); ++j) {
        round[r + j * ranks] = std::move(theirs[j]);
      }
    }
    if (done) {
      for (const TrialResult& t : round) done(t);
    }
    return round;
  });
}

int trial_worlds_on_root(FosResult& result, const World& consolidated, const FosSettings& per_rank,
                         const std::vector<double>& factors, const StopQuery& stop) {
  if (!is_root_rank() || rank_count() == 1) return 0;
  std::vector<std::size_t> missing;
  std::vector<double> again;
  for (std::size_t k = 0; k < result.trials.size(); ++k) {
    const TrialResult& t = result.trials[k];
    bool wanted = false;
    for (double f : factors) wanted = wanted || t.factor == f;
    // A trial that ran here has the consolidated world's blocks; one gathered has none.
    if (wanted && !t.interrupted && t.world.blocks.empty()) {
      missing.push_back(k);
      again.push_back(t.factor);
    }
  }
  if (again.empty()) return 0;
  std::vector<TrialResult> rerun = run_trials(consolidated, per_rank, again, {}, stop);
  for (std::size_t j = 0; j < missing.size(); ++j) {
    result.trials[missing[j]].world = std::move(rerun[j].world);
  }
  return static_cast<int>(again.size());
}

}  // namespace dda
