#include "studies/probabilistic_fos.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

namespace dda {
namespace {

SampleOutcome run_sample(const World& consolidated, const std::vector<JointMaterial>& scene_joints,
                         const RandomStrengths& spec, const FosSettings& settings,
                         const ProbabilisticSettings& p, long index, const StopQuery& stop) {
  const auto start = std::chrono::steady_clock::now();
  SampleOutcome out;
  out.index = index;
  out.values = draw_sample(spec, p.seed, static_cast<std::uint64_t>(index));
  const World world = with_sampled_strengths(consolidated, scene_joints, spec, out.values);
  if (p.at_factor > 0.0) {
    const TrialResult t = run_trial(world, settings, p.at_factor, stop);
    out.done = !t.interrupted;
    out.failing = !t.stable;
    out.verdict = t.verdict;
    out.trials = 1;
    out.steps = t.steps;
  } else {
    // One trial per round: the search's path then depends on the verdicts alone, never on
    // the number of threads (FosSettings::jobs sets the round's width).
    FosSettings one = settings;
    one.jobs = 1;
    one.first_failing_guess = 0.0;
    const FosResult r = find_factor_of_safety(one, [&](const std::vector<double>& factors) {
      std::vector<TrialResult> trials;
      for (double f : factors) trials.push_back(run_trial(world, one, f, stop));
      return trials;
    });
    out.done = !r.interrupted;
    out.factor_found = r.found;
    out.factor = r.factor_of_safety;
    out.last_stable = r.last_stable;
    out.first_failing = r.first_failing;
    out.message = r.message;
    out.trials = static_cast<int>(r.trials.size());
    bool any_stable = false, any_failing = false;
    for (const TrialResult& t : r.trials) {
      out.steps += t.steps;
      if (!t.interrupted) (t.stable ? any_stable : any_failing) = true;
      // next_factors starts every search at F = 1: its verdict is the sample's at F = 1.
      if (t.factor == 1.0 && !t.interrupted) {
        out.failing = !t.stable;
        out.verdict = t.verdict;
      }
    }
    out.above_range = out.done && !r.found && !any_failing;
    out.below_range = out.done && !r.found && !any_stable;
  }
  out.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace

ProbabilisticSummary summarise(const std::vector<SampleOutcome>& samples) {
  ProbabilisticSummary s;
  double sum = 0.0;
  for (const SampleOutcome& o : samples) {
    if (!o.done) continue;
    ++s.judged;
    if (o.failing) ++s.failing;
    if (o.factor_found) {
      if (s.factors == 0) s.min_factor = s.max_factor = o.factor;
      ++s.factors;
      sum += o.factor;
      s.min_factor = std::min(s.min_factor, o.factor);
      s.max_factor = std::max(s.max_factor, o.factor);
    }
    if (o.above_range) ++s.above_range;
    if (o.below_range) ++s.below_range;
  }
  if (s.judged > 0) s.probability_of_failure = static_cast<double>(s.failing) / static_cast<double>(s.judged);
  s.interval = wilson_interval(s.failing, s.judged);
  if (s.factors > 0) {
    s.mean_factor = sum / static_cast<double>(s.factors);
    double squares = 0.0;
    for (const SampleOutcome& o : samples) {
      if (o.done && o.factor_found) squares += (o.factor - s.mean_factor) * (o.factor - s.mean_factor);
    }
    if (s.factors > 1) s.factor_standard_deviation = std::sqrt(squares / static_cast<double>(s.factors - 1));
  }
  return s;
}

ProbabilisticResult run_probabilistic(const World& consolidated,
                                      const std::vector<JointMaterial>& scene_joints,
                                      const RandomStrengths& spec, const FosSettings& settings,
                                      const ProbabilisticSettings& p,
                                      const std::function<void(const SampleOutcome&)>& done,
                                      const StopQuery& stop) {
  ProbabilisticResult result;
  result.settings = p;
  result.judged_at = p.at_factor > 0.0 ? p.at_factor : 1.0;
  result.samples.resize(static_cast<std::size_t>(std::max(0L, p.samples)));
  for (std::size_t k = 0; k < result.samples.size(); ++k) {
    result.samples[k].index = static_cast<long>(k);
  }
  std::mutex lock;
  const auto shares = static_cast<std::size_t>(std::max(1L, p.shares));
  const auto share = static_cast<std::size_t>(std::clamp(p.share, 0L, std::max(1L, p.shares) - 1));
  std::size_t next = share;
  // Each worker takes the next sample; a sample owns its world and its generator, so the
  // workers share nothing but the queue (as run_trials' do).
  auto worker = [&] {
    for (;;) {
      std::size_t k = 0;
      {
        const std::lock_guard<std::mutex> guard(lock);
        if (next >= result.samples.size() || (stop && stop())) return;
        k = next;
        next += shares;
      }
      SampleOutcome o = run_sample(consolidated, scene_joints, spec, settings, p,
                                   static_cast<long>(k), stop);
      const std::lock_guard<std::mutex> guard(lock);
      if (o.done && done) done(o);
      result.samples[k] = std::move(o);
    }
  };
  const std::size_t mine = (result.samples.size() + shares - 1 - share) / shares;
  const std::size_t threads =
      std::min<std::size_t>(mine, static_cast<std::size_t>(std::max(1, settings.jobs)));
  std::vector<std::thread> pool;
  for (std::size_t i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  for (std::size_t k = share; k < result.samples.size(); k += shares) {
    result.interrupted = result.interrupted || !result.samples[k].done;
  }
  result.summary = summarise(result.samples);
  return result;
}

void add_samples(ProbabilisticResult& result, std::vector<SampleOutcome> outcomes) {
  for (SampleOutcome& o : outcomes) {
    if (o.index < 0 || o.index >= static_cast<long>(result.samples.size())) continue;
    result.samples[static_cast<std::size_t>(o.index)] = std::move(o);
  }
  result.interrupted = false;
  for (const SampleOutcome& o : result.samples) result.interrupted = result.interrupted || !o.done;
  result.summary = summarise(result.samples);
}

}  // namespace dda
