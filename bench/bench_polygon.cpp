// The reader's simplicity check: a block outline of n vertices on a circle, by
// the sweep along x that the reader uses and by the all-pairs reference. Before the sweep an
// 80 000-vertex polygon took 21 s to read. Run:
//   build/release/dda_bench --benchmark_filter=Simplicity
#include <benchmark/benchmark.h>

#include <cmath>

#include "kinematics/polygon.hpp"

namespace {

dda::Polygon circle(int n) {
  dda::Polygon poly(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * M_PI * k / n;
    poly[static_cast<std::size_t>(k)] = dda::Vec2(std::cos(angle), std::sin(angle));
  }
  return poly;
}

void BM_SimplicitySweep(benchmark::State& state) {
  const dda::Polygon poly = circle(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(dda::is_self_intersecting(poly));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_SimplicitySweep)->Arg(1000)->Arg(10000)->Arg(80000)->Unit(benchmark::kMillisecond)->Complexity();

void BM_SimplicityReference(benchmark::State& state) {
  const dda::Polygon poly = circle(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(dda::is_self_intersecting_reference(poly));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_SimplicityReference)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond)->Complexity();

}  // namespace
