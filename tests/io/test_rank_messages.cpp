// The messages between the ranks of an MPI run (io/rank_messages.hpp): a trial's result and
// a sample's outcome come back from their bytes as they went, to the last bit, since rank 0
// writes the gathered numbers into the same report a one-process run writes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include "io/rank_messages.hpp"

namespace {

using namespace dda;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TrialResult odd_trial(double factor) {
  TrialResult t;
  t.factor = factor;
  t.stable = factor < 1.0;
  t.verdict = "moved beyond the failure displacement, \"quoted\"\nand a line";
  t.largest_displacement = 0.1 + 0.2;  // not a short decimal
  t.end_speed = std::numeric_limits<double>::denorm_min();
  t.end_speed_limit = -0.0;
  t.predicted_displacement = std::numeric_limits<double>::infinity();
  t.kinetic_peak = 1e300;
  t.steps = 1234;
  t.stats.steps = 1234;
  t.stats.cut_steps = 7;
  t.stats.iterations = 99999999999L;
  t.stats.stage_times.solve = 1.0 / 3.0;
  t.stats.message = "";
  t.stats.broken_bonds.push_back({3, 0.125, 4, 5, Vec2(1.0 / 7.0, -2.5)});
  t.simulated_time = 2.5;
  t.watched_point = 17;
  return t;
}

}  // namespace

TEST_CASE("trial results come back from their bytes bit for bit", "[ranks][io]") {
  // Built one by one: an initializer list of worlds draws GCC 12's false "maybe
  // uninitialized" from the vectors inside World.
  std::vector<TrialResult> sent;
  sent.push_back(odd_trial(0.75));
  sent.push_back(odd_trial(1.5));
  sent.emplace_back();
  const std::vector<TrialResult> got = unpack_trials(pack_trials(sent));
  REQUIRE(got.size() == 3);
  const TrialResult& a = sent[0];
  const TrialResult& b = got[0];
  CHECK(b.factor == a.factor);
  CHECK(b.stable == a.stable);
  CHECK(b.verdict == a.verdict);
  CHECK(same_bits(b.largest_displacement, a.largest_displacement));
  CHECK(same_bits(b.end_speed, a.end_speed));
  CHECK(std::signbit(b.end_speed_limit));  // -0 stays -0
  REQUIRE(b.predicted_displacement.has_value());
  CHECK(std::isinf(*b.predicted_displacement));
  CHECK(b.kinetic_peak == a.kinetic_peak);
  CHECK(b.steps == 1234);
  CHECK(b.stats.cut_steps == 7);
  CHECK(b.stats.iterations == 99999999999L);
  CHECK(same_bits(b.stats.stage_times.solve, a.stats.stage_times.solve));
  REQUIRE(b.stats.broken_bonds.size() == 1);
  CHECK(b.stats.broken_bonds[0].edge_block == 5);
  CHECK(same_bits(b.stats.broken_bonds[0].at.x(), 1.0 / 7.0));
  CHECK(b.watched_point == 17);
  CHECK(got[1].factor == 1.5);
  CHECK_FALSE(got[2].predicted_displacement.has_value());
  CHECK(got[2].verdict.empty());
}

TEST_CASE("sample outcomes come back from their bytes bit for bit", "[ranks][io]") {
  SampleOutcome o;
  o.index = 41;
  o.values = {32.123456789012345, 0.1 + 0.2};
  o.done = true;
  o.failing = true;
  o.verdict = "moved beyond the failure displacement";
  o.factor_found = true;
  o.factor = 0.987654321;
  o.last_stable = 0.98;
  o.first_failing = 0.99;
  o.trials = 9;
  o.steps = 123456;
  o.wall_time_s = 0.25;
  const std::vector<SampleOutcome> got = unpack_samples(pack_samples({o, SampleOutcome{}}));
  REQUIRE(got.size() == 2);
  CHECK(got[0].index == 41);
  CHECK(got[0].values == o.values);
  CHECK(got[0].failing);
  CHECK(got[0].verdict == o.verdict);
  CHECK(got[0].factor == o.factor);
  CHECK(got[0].trials == 9);
  CHECK(got[0].steps == 123456);
  CHECK(got[1].values.empty());
  CHECK_FALSE(got[1].done);
}

TEST_CASE("a message cut short is an error and not a result", "[ranks][io]") {
  const std::string bytes = pack_trials({odd_trial(1.0)});
  CHECK_THROWS_AS(unpack_trials(bytes.substr(0, bytes.size() - 3)), std::runtime_error);
  CHECK_THROWS_AS(unpack_trials(bytes + "x"), std::runtime_error);
}
