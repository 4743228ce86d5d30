// Cost of a DDA step with plastic blocks against the same scene elastic: a packed
// wall of 100 bricks (as BM_PackedWall) whose bricks are (0) elastic, (1) Mohr-Coulomb that
// never yields (cohesion 1 GPa), or (2) Mohr-Coulomb that yields under its own weight
// (cohesion 10 kPa against ~1e5 Pa of self-weight stress). (0) is the price of elastic
// scenes (they never touch the material library); (1) is the price of the Newton machinery
// when nothing yields (one material call per block per iteration); (2) adds the Newton
// iterations of real plastic flow. Run:
//   build/release/dda_bench --benchmark_filter=PlasticWall
#include <benchmark/benchmark.h>

#include <cmath>

#include "brick_wall.hpp"
#include "solver/step.hpp"
#include "solver/world.hpp"

namespace {

dda::World wall(int n, int variant) {
  dda::Material m = dda::elastic_material("rock", 2700.0, 1e9, 0.25);
  if (variant > 0) {
    m.parameters.model_parameters =
        dda::plastic_parameters<dda::MohrCoulombParameters>(variant == 1 ? 1e9 : 1e4, 30.0, 30.0);
  }
  return dda::make_world(dda::bench::brick_wall_scene(n, m));
}

void BM_PlasticWall(benchmark::State& state) {
  const int variant = static_cast<int>(state.range(0));
  dda::World world = wall(100, variant);
  dda::StepWorkspace ws;
  dda::RunStats warmup;
  for (int k = 0; k < 5; ++k) dda::advance_step(world, ws, warmup);
  dda::RunStats stats;
  for (auto _ : state) {
    const dda::StepOutcome outcome = dda::advance_step(world, ws, stats);
    if (!outcome.ok) state.SkipWithError(outcome.message.c_str());
  }
  const double steps = static_cast<double>(state.iterations());
  state.counters["iterations_per_step"] = static_cast<double>(stats.iterations) / steps;
  state.counters["block_steps_per_s"] =
      benchmark::Counter(100.0, benchmark::Counter::kIsIterationInvariantRate);
  double eps_p = 0.0;
  for (const dda::Block& b : world.blocks) eps_p = std::max(eps_p, b.material_state.eps_p);
  state.counters["max_eps_p"] = eps_p;
}
BENCHMARK(BM_PlasticWall)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
