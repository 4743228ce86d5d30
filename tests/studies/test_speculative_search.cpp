// The factor-of-safety search on threads that run ahead of the verdicts: it must run the
// search of find_factor_of_safety exactly (same trials, verdicts, factor and message) however
// its trials interleave, start the next round's trial while a slow one runs, and drop what a
// wrong prediction started. Made-up verdicts; the trials' durations (sleeps) only change the
// interleaving, never an assertion.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <set>
#include <thread>

#include "studies/speculative_search.hpp"
#include "support/fos_checks.hpp"

namespace {

using namespace dda;
using namespace std::chrono_literals;

// A made-up verdict: stable below the threshold and, when `window` is set, also in
// [threshold + 0.03, threshold + 0.05] (verdicts not monotone in F, as near a chaotic factor).
struct Verdict {
  double threshold = 1.0;
  bool window = false;
  bool stable(double f) const {
    return f < threshold || (window && f >= threshold + 0.03 && f <= threshold + 0.05);
  }
};

TrialResult judged(double f, bool stable) {
  TrialResult t;
  t.factor = f;
  t.stable = stable;
  t.verdict = stable ? "at rest" : "moving faster than the speed limit";
  return t;
}

// Failing trials take longer than stable ones, as they do on slopes; the runner honours
// `stop` between its slices of sleep.
TrialRunner sleeping_runner(const Verdict& v) {
  return [v](double f, const StopQuery& stop) {
    const bool stable = v.stable(f);
    const int slices = stable ? 1 : 4;
    for (int k = 0; k < slices; ++k) {
      if (stop && stop()) {
        TrialResult t;
        t.factor = f;
        t.interrupted = true;
        t.verdict = "interrupted";
        return t;
      }
      std::this_thread::sleep_for(500us);
    }
    return judged(f, stable);
  };
}

FosResult one_round_at_a_time(const FosSettings& s, const Verdict& v) {
  return find_factor_of_safety(s, [&v](const std::vector<double>& factors) {
    std::vector<TrialResult> out;
    for (double f : factors) out.push_back(judged(f, v.stable(f)));
    return out;
  });
}

void check_same_search(const FosResult& threads, const FosResult& rounds) {
  CHECK(threads.found == rounds.found);
  CHECK(threads.interrupted == rounds.interrupted);
  CHECK(threads.factor_of_safety == rounds.factor_of_safety);
  CHECK(threads.last_stable == rounds.last_stable);
  CHECK(threads.first_failing == rounds.first_failing);
  CHECK(threads.message == rounds.message);
  REQUIRE(threads.trials.size() == rounds.trials.size());
  for (std::size_t k = 0; k < rounds.trials.size(); ++k) {
    CHECK(threads.trials[k].factor == rounds.trials[k].factor);
    CHECK(threads.trials[k].stable == rounds.trials[k].stable);
  }
}

}  // namespace

TEST_CASE("the search on threads runs exactly the search of one round at a time", "[fos]") {
  // Thresholds inside the range, at 1 (the first trial), and beyond both ends (no factor);
  // no guess, a good one (the 1965-block slope's limit analysis, 1.174) and a bad one.
  for (int jobs : {1, 2, 3}) {
    for (double threshold : {0.05, 0.37, 1.0 + 1e-9, 1.093, 1.2, 3.7, 12.0}) {
      for (double guess : {0.0, 1.174, 0.5}) {
        for (bool window : {false, true}) {
          FosSettings s;
          s.jobs = jobs;
          s.first_failing_guess = guess;
          const Verdict v{threshold, window};
          INFO("jobs " << jobs << ", threshold " << threshold << ", guess " << guess
                       << ", window " << window);
          int reported = 0;
          const FosResult r = search_on_threads(s, sleeping_runner(v),
                                                [&reported](const TrialResult&) { ++reported; });
          check_same_search(r, one_round_at_a_time(s, v));
          // Every trial judged is reported once; the search's own are among them.
          CHECK(reported >= static_cast<int>(r.trials.size()));
          CHECK(reported + r.discarded_trials >= static_cast<int>(r.trials.size()));
          if (jobs == 1) CHECK(r.discarded_trials == 0);  // one thread: nothing run ahead
        }
      }
    }
  }
}

TEST_CASE("the plan runs ahead of a running trial on the verdict predicted for it", "[fos]") {
  FosSettings s;
  s.jobs = 2;
  s.first_failing_guess = 1.174;
  // F = 1 stood; the guess runs and is predicted to fail (failing trials are the slow ones),
  // so the next round, trisecting [1, 1.174], is wanted after it.
  const SearchPlan plan = plan_search({judged(1.0, true)}, s, 2);
  CHECK_FALSE(plan.done);
  REQUIRE(plan.wanted.size() == 3);
  CHECK(plan.wanted[0] == 1.174);
  CHECK(plan.wanted[1] == Approx(1.058));
  CHECK(plan.wanted[2] == Approx(1.116));
  CHECK(plan.path.empty());  // the first round is not judged in full
  REQUIRE(plan.frontier.size() == 2);
  CHECK(plan.frontier[1] == 1.174);
  // Predictions: monotone in F where a verdict says so, stable at or below the
  // consolidation's factor, failing otherwise.
  CHECK(predicted_stable(1.05, {judged(1.1, true)}, 1.0));
  CHECK_FALSE(predicted_stable(1.05, {judged(1.02, false), judged(1.1, true)}, 1.0));
  CHECK(predicted_stable(0.9, {}, 1.0));
  CHECK_FALSE(predicted_stable(1.3, {judged(1.0, true)}, 1.0));
  // Every round judged: done, and the path is the search's.
  const Verdict v{1.093, false};
  const FosResult rounds = one_round_at_a_time(s, v);
  const SearchPlan end = plan_search(rounds.trials, s, 2);
  CHECK(end.done);
  CHECK(end.path.size() == rounds.trials.size());
}

TEST_CASE("a free thread starts the next round while a slow trial runs, and a wrong "
          "prediction is stopped and dropped",
          "[fos]") {
  // Each trial here waits for an event of the search (with a timeout, so a search that does
  // not run ahead fails the test instead of hanging it).
  std::mutex m;
  std::condition_variable cv;
  std::set<double> started;
  const auto wait_for_start = [&](double f) {
    std::unique_lock<std::mutex> lock(m);
    return cv.wait_for(lock, 20s, [&] {
      for (double g : started) {
        if (std::abs(g - f) < 1e-9) return true;
      }
      return false;
    });
  };
  const auto mark_started = [&](double f) {
    const std::lock_guard<std::mutex> lock(m);
    started.insert(f);
    cv.notify_all();
  };
  FosSettings s;
  s.jobs = 2;
  s.first_failing_guess = 1.174;

  SECTION("the guess fails slowly: the next round's first trial starts before it ends") {
    const Verdict v{1.093, false};
    bool ran_ahead = true;
    const TrialRunner run = [&](double f, const StopQuery&) {
      mark_started(f);
      if (f == 1.174) ran_ahead = wait_for_start(1.0 + 0.174 / 3);
      return judged(f, v.stable(f));
    };
    const FosResult r = search_on_threads(s, run, {});
    CHECK(ran_ahead);
    check_same_search(r, one_round_at_a_time(s, v));
  }
  SECTION("the guess stands, slowly: the trial started on its predicted failure is dropped") {
    const Verdict v{2.5, false};
    bool ran_ahead = true;
    bool stopped = false;
    const TrialRunner run = [&](double f, const StopQuery& stop) {
      mark_started(f);
      if (f == 1.174) ran_ahead = wait_for_start(1.0 + 0.174 / 3);
      if (std::abs(f - (1.0 + 0.174 / 3)) < 1e-9) {
        // Runs until the plan, told that 1.174 stands, stops it.
        const auto give_up = std::chrono::steady_clock::now() + 20s;
        while (!(stop && stop()) && std::chrono::steady_clock::now() < give_up) {
          std::this_thread::sleep_for(1ms);
        }
        stopped = stop && stop();
        TrialResult t = judged(f, v.stable(f));
        t.interrupted = stopped;
        return t;
      }
      return judged(f, v.stable(f));
    };
    const FosResult r = search_on_threads(s, run, {});
    CHECK(ran_ahead);
    CHECK(stopped);
    CHECK(r.discarded_trials >= 1);
    check_same_search(r, one_round_at_a_time(s, v));
  }
}

TEST_CASE("a search on threads that is stopped keeps the bracket of its judged trials",
          "[fos]") {
  // As find_factor_of_safety's stopped search (test_strength_reduction.cpp): one job, a
  // threshold of 1.37, F = 1 stands, 2 fails, 1.5 fails, and the stop comes before the fourth
  // trial, which is kept in the list, interrupted.
  FosSettings one;
  one.jobs = 1;
  int judged_trials = 0;
  const Verdict v{1.37, false};
  const FosResult r = search_on_threads(
      one, sleeping_runner(v), [&judged_trials](const TrialResult&) { ++judged_trials; },
      [&judged_trials] { return judged_trials >= 3; });
  test::check_stopped_after_three_trials(r);
  CHECK(r.trials.back().factor == 1.25);
}
