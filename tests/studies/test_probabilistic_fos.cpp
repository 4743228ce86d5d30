// The probabilistic factor of safety (studies/probabilistic_fos.hpp) of a block on an
// inclined plane whose joint friction angle is normally distributed, against its closed
// form P(F < 1) = P(phi < alpha) = Phi((alpha - mu) / sigma).
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>

#include "io/scene_reader.hpp"
#include "studies/probabilistic_fos.hpp"
#include "support/plane_block_scene.hpp"

namespace {

using namespace dda;

Consolidation consolidated(const Scene& scene) {
  Consolidation c = consolidate(scene, 1.0, [](const World&, const RunStats&) { return true; });
  REQUIRE_FALSE(c.stats.diverged);
  return c;
}

}  // namespace

TEST_CASE("the probability of failure of a block on a plane with a normal friction angle is "
          "Phi((alpha - mu) / sigma)",
          "[fos][random]") {
  // alpha = 30, phi ~ N(32, 4) (truncated to [10, 54], 5.5 sigma away: a change of 4e-8):
  // P = Phi(-0.5) = 0.3085. Consolidated at phi = 32 > alpha, the block stands.
  const double alpha = 30.0, mu = 32.0, sigma = 4.0;
  const Scene scene = parse_scene_text(
      test::with_random_friction(test::plane_block_scene(alpha, mu), mu, sigma, 10.0, 54.0).dump(),
      "plane");
  REQUIRE(scene.random_strengths.variables.size() == 1);
  const Consolidation c = consolidated(scene);
  FosSettings s = resolve_fos_settings(c.world, FosSettings{}, c.settling.relaxation_steps);
  s.jobs = 2;
  ProbabilisticSettings p;
  p.samples = 1000;
  p.seed = 1;
  p.at_factor = 1.0;
  const auto start = std::chrono::steady_clock::now();
  const ProbabilisticResult r =
      run_probabilistic(c.world, scene.joint_materials, scene.random_strengths, s, p, {});
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double closed_form = standard_normal_cdf((alpha - mu) / sigma);
  INFO("P = " << r.summary.probability_of_failure << " in [" << r.summary.interval.low << ", "
              << r.summary.interval.high << "], closed form " << closed_form << ", " << wall << " s");
  REQUIRE(r.summary.judged == 1000);
  REQUIRE_FALSE(r.interrupted);
  // With N = 1000 the Wilson interval is about +-0.029 wide. The verdict has a resolution: a
  // block whose phi lies below alpha slides at a = g sin(alpha) (1 - tan(phi) / tan(alpha)),
  // and a trial resolves accelerations down to detect_acceleration g = 0.002 g, so a phi
  // within about 0.002 cos(alpha) rad = 0.1 degree below alpha may be judged stable.
  // The normal density at alpha is 0.088 per degree: at most 0.009 of the probability moves,
  // a third of the interval's half-width, and the check below allows it.
  CHECK(r.summary.interval.low <= closed_form);
  CHECK(closed_form <= r.summary.interval.high);
  // Every sample's verdict agrees with phi against alpha outside that band.
  int disagreements = 0;
  for (const SampleOutcome& o : r.samples) {
    const double phi = o.values.at(0);
    if (std::abs(phi - alpha) < 0.15) continue;
    if (o.failing != (phi < alpha)) ++disagreements;
  }
  CHECK(disagreements == 0);
}

TEST_CASE("a sample's factor of a block on a plane is tan(phi) / tan(alpha), whatever the "
          "number of threads",
          "[fos][random]") {
  const double alpha = 30.0;
  const Scene scene = parse_scene_text(
      test::with_random_friction(test::plane_block_scene(alpha, 35.0), 35.0, 4.0, 20.0, 50.0).dump(),
      "plane");
  const Consolidation c = consolidated(scene);
  FosSettings s = resolve_fos_settings(c.world, FosSettings{}, c.settling.relaxation_steps);
  ProbabilisticSettings p;
  p.samples = 3;
  p.seed = 5;
  s.jobs = 1;
  const ProbabilisticResult one =
      run_probabilistic(c.world, scene.joint_materials, scene.random_strengths, s, p, {});
  s.jobs = 2;
  const ProbabilisticResult two =
      run_probabilistic(c.world, scene.joint_materials, scene.random_strengths, s, p, {});
  for (std::size_t k = 0; k < 3; ++k) {
    const SampleOutcome& o = one.samples[k];
    REQUIRE(o.factor_found);
    const double le = std::tan(o.values[0] * M_PI / 180.0) / std::tan(alpha * M_PI / 180.0);
    // The search's budget (tests/studies/test_strength_reduction.cpp): half the bracket plus
    // the verdict's resolution F x 2 x 0.002 / sin(alpha).
    CHECK(std::abs(o.factor - le) <= 0.5 * s.tolerance + le * 2.0 * s.detect_acceleration / 0.5);
    CHECK(o.failing == (o.factor < 1.0));
    // Threads change nothing: the same draws, the same trials, the same factor.
    CHECK(two.samples[k].values == o.values);
    CHECK(two.samples[k].factor == o.factor);
  }
  CHECK(two.summary.mean_factor == one.summary.mean_factor);
}

TEST_CASE("samples shared out in parts and put together are the samples of one run",
          "[fos][random][ranks]") {
  // What the ranks of an MPI run do with --samples (docs/mpi.md): rank r of R runs the
  // samples k with k % R == r, rank 0 puts the others' in. Each sample's draw depends on the
  // seed and k alone, so the whole must equal one run's to the last bit, whatever the parts.
  const Scene scene = parse_scene_text(
      test::with_random_friction(test::plane_block_scene(30.0, 32.0), 32.0, 4.0, 10.0, 54.0).dump(),
      "plane");
  const Consolidation c = consolidated(scene);
  FosSettings s = resolve_fos_settings(c.world, FosSettings{}, c.settling.relaxation_steps);
  s.jobs = 2;
  ProbabilisticSettings p;
  p.samples = 7;
  p.seed = 5;
  p.at_factor = 1.0;
  const ProbabilisticResult whole =
      run_probabilistic(c.world, scene.joint_materials, scene.random_strengths, s, p, {});
  p.shares = 3;
  std::vector<ProbabilisticResult> parts;
  for (long r = 0; r < 3; ++r) {
    p.share = r;
    parts.push_back(run_probabilistic(c.world, scene.joint_materials, scene.random_strengths, s, p, {}));
    // A part judges its own samples only (7 = 3 + 2 + 2).
    CHECK(parts.back().summary.judged == (r == 0 ? 3 : 2));
    CHECK_FALSE(parts.back().interrupted);
  }
  // Rank 0's result takes the others' own samples (what app/fos_samples.cpp gathers).
  const auto own = [](const ProbabilisticResult& part) {
    std::vector<SampleOutcome> out;
    for (const SampleOutcome& o : part.samples) {
      if (o.done) out.push_back(o);
    }
    return out;
  };
  ProbabilisticResult joined = parts[0];
  add_samples(joined, own(parts[1]));
  // Samples 2 and 5 not yet in: not all judged, and said so.
  CHECK(joined.interrupted);
  CHECK(joined.summary.judged == 5);
  add_samples(joined, own(parts[2]));
  REQUIRE_FALSE(joined.interrupted);
  REQUIRE(joined.samples.size() == whole.samples.size());
  for (std::size_t k = 0; k < whole.samples.size(); ++k) {
    CHECK(joined.samples[k].values == whole.samples[k].values);
    CHECK(joined.samples[k].failing == whole.samples[k].failing);
    CHECK(joined.samples[k].verdict == whole.samples[k].verdict);
    CHECK(joined.samples[k].steps == whole.samples[k].steps);
  }
  CHECK(joined.summary.failing == whole.summary.failing);
  CHECK(joined.summary.probability_of_failure == whole.summary.probability_of_failure);
  CHECK(joined.summary.interval.low == whole.summary.interval.low);
}
