// Cost of one DDA step's assembly plus CHOLMOD solve for N free blocks (no contacts yet),
// and of a whole step (assembly, solve, displacement check, update). Run:
//   build/release/dda_bench --benchmark_filter=Step
#include <benchmark/benchmark.h>

#include "solver/assembly.hpp"
#include "solver/step.hpp"
#include "solver/world.hpp"

namespace {

// N unit squares on a square grid with gaps (so that they could never touch), under gravity.
dda::World grid_of_blocks(int n) {
  dda::Scene s;
  s.materials.push_back(dda::elastic_material("rock", 2700.0, 1e9, 0.25));
  s.control.time_steps = {0.001};
  s.control.steps = 1 << 30;
  int side = 1;
  while (side * side < n) ++side;
  // 1 cm a step at most (the blocks move ~4e-4 m a step): the contact search distance,
  // 2.5 x ratio x w0 = 2.5 cm, stays below the 1 m gaps, so no pair is ever looked at in the
  // narrow phase. (A ratio of 1 made it 2.5 w0: every pair a candidate, a dense system.)
  const double w0 = 0.5 * (2.0 * side - 1.0);
  s.control.max_displacement_ratio = 0.01 / w0;
  for (int i = 0; i < n; ++i) {
    const double x = 2.0 * (i % side), y = 2.0 * (i / side);
    dda::BlockSpec b;
    b.vertices = {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
    b.velocity = dda::Vec3(0.1, 0.0, 0.5);
    s.blocks.push_back(b);
  }
  return dda::make_world(s);
}

void BM_AssembleAndSolve(benchmark::State& state) {
  dda::World world = grid_of_blocks(static_cast<int>(state.range(0)));
  dda::StepWorkspace ws;
  dda::StepContext ctx;
  ctx.dt = 0.001;
  ctx.penalty = world.penalty;
  ctx.dynamic_coefficient = 1.0;
  for (auto _ : state) {
    dda::assemble(world, ctx, ws.system);
    auto d = ws.solver.solve(ws.system);
    benchmark::DoNotOptimize(d);
  }
  state.counters["block_steps_per_s"] =
      benchmark::Counter(static_cast<double>(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_AssembleAndSolve)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_WholeStep(benchmark::State& state) {
  dda::World world = grid_of_blocks(static_cast<int>(state.range(0)));
  dda::StepWorkspace ws;
  dda::RunStats stats;
  for (auto _ : state) {
    auto outcome = dda::advance_step(world, ws, stats);
    benchmark::DoNotOptimize(outcome);
  }
  state.counters["block_steps_per_s"] =
      benchmark::Counter(static_cast<double>(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_WholeStep)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

}  // namespace


