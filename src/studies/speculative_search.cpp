#include "studies/speculative_search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

namespace dda {
namespace {

const TrialResult* judged_at(const std::vector<TrialResult>& judged, double factor) {
  for (const TrialResult& t : judged) {
    if (t.factor == factor && !t.interrupted) return &t;
  }
  return nullptr;
}

bool listed(const std::vector<double>& factors, double f) {
  return std::find(factors.begin(), factors.end(), f) != factors.end();
}

}  // namespace

bool predicted_stable(double factor, const std::vector<TrialResult>& known,
                      double consolidation_factor) {
  for (const TrialResult& t : known) {
    if (!t.interrupted && !t.stable && t.factor <= factor) return false;
  }
  for (const TrialResult& t : known) {
    if (!t.interrupted && t.stable && t.factor >= factor) return true;
  }
  return factor <= consolidation_factor;
}

SearchPlan plan_search(const std::vector<TrialResult>& judged, const FosSettings& s,
                       int threads) {
  SearchPlan plan;
  // The search's trials as find_factor_of_safety would have them, judged where they are and
  // assumed (predicted_stable) where they are not yet.
  std::vector<TrialResult> assumed;
  bool complete = true;  // every round so far judged: its trials are the search's path
  // The search ends within a few dozen rounds (find_factor_of_safety); the cap only guards
  // a planning mistake.
  for (int round = 0; round < 1000; ++round) {
    const std::vector<double> factors = next_factors(assumed, s);
    if (factors.empty()) {
      plan.done = complete;
      return plan;
    }
    std::vector<TrialResult> in_round;
    for (double f : factors) {
      if (const TrialResult* t = judged_at(judged, f)) in_round.push_back(*t);
    }
    if (complete && in_round.size() == factors.size()) {
      plan.path.insert(plan.path.end(), in_round.begin(), in_round.end());
    } else if (complete) {
      plan.frontier = factors;
    }
    // Predictions see the path so far, this round's judged trials and its earlier predictions.
    std::vector<TrialResult> known = assumed;
    known.insert(known.end(), in_round.begin(), in_round.end());
    for (double f : factors) {
      if (const TrialResult* t = judged_at(judged, f)) {
        assumed.push_back(*t);
        continue;
      }
      complete = false;
      if (!listed(plan.wanted, f)) plan.wanted.push_back(f);
      TrialResult guess;
      guess.factor = f;
      guess.stable = predicted_stable(f, known, s.consolidation_factor);
      known.push_back(guess);
      assumed.push_back(guess);
    }
    if (static_cast<int>(plan.wanted.size()) >= threads) return plan;
  }
  return plan;
}

FosResult search_on_threads(const FosSettings& s, const TrialRunner& run,
                            const std::function<void(const TrialResult&)>& done,
                            const StopQuery& stop) {
  const int threads = std::max(1, s.jobs);
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<TrialResult> judged;
  // The trials running, each with the flag that stops it when the plan drops it.
  std::map<double, std::shared_ptr<std::atomic<bool>>> running;
  std::map<double, TrialResult> stopped;  // ended by `stop`, not by the plan
  int discarded = 0;                       // trials the plan stopped, and their time (s)
  double discarded_wall_time_s = 0.0;
  bool stopping = false;
  const auto asked_to_stop = [&stop] { return stop && stop(); };

  // Each thread: plan from every verdict so far, stop the trials the plan no longer wants,
  // start the first wanted trial nobody runs, or wait for a verdict to change the plan.
  const auto worker = [&] {
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
      if (stopping || asked_to_stop()) {
        stopping = true;
        for (auto& entry : running) entry.second->store(true);
        changed.notify_all();
        return;
      }
      const SearchPlan plan = plan_search(judged, s, threads);
      for (auto& [f, flag] : running) {
        if (!listed(plan.wanted, f)) flag->store(true);
      }
      if (plan.done) {
        changed.notify_all();
        return;
      }
      const auto first_idle = std::find_if(plan.wanted.begin(), plan.wanted.end(),
                                           [&running](double f) { return running.count(f) == 0; });
      if (first_idle == plan.wanted.end()) {
        // A verdict changes the plan; the timeout only lets a waiting thread see `stop`.
        changed.wait_for(lock, std::chrono::milliseconds(100));
        continue;
      }
      const double next = *first_idle;
      const auto flag = std::make_shared<std::atomic<bool>>(false);
      running.emplace(next, flag);
      lock.unlock();
      TrialResult r = run(next, [&asked_to_stop, flag] { return flag->load() || asked_to_stop(); });
      lock.lock();
      running.erase(next);
      if (!r.interrupted) {
        if (done) done(r);
        judged.push_back(std::move(r));
      } else if (stopping || asked_to_stop()) {
        stopped[next] = std::move(r);
      } else {
        ++discarded;
        discarded_wall_time_s += r.wall_time_s;
      }
      changed.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();

  const SearchPlan plan = plan_search(judged, s, threads);
  std::vector<TrialResult> trials = plan.path;
  const bool interrupted = !plan.done;
  if (interrupted) {
    // The round the stop cut short, in its order: its trials judged, stopped or never started.
    for (double f : plan.frontier) {
      if (const TrialResult* t = judged_at(judged, f)) {
        trials.push_back(*t);
        continue;
      }
      auto it = stopped.find(f);
      if (it != stopped.end()) {
        trials.push_back(std::move(it->second));
      } else {
        TrialResult t;
        t.factor = f;
        t.interrupted = true;
        t.verdict = "interrupted";
        trials.push_back(std::move(t));
      }
    }
  }
  FosResult result = conclude_search(std::move(trials), interrupted, s);
  result.discarded_trials = discarded;
  result.discarded_wall_time_s = discarded_wall_time_s;
  return result;
}

}  // namespace dda
