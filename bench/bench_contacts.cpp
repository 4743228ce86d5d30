// One DDA step of a packed brick wall resting on a fixed base: N bricks 1 m x 0.5 m in
// offset rows, under gravity, with Mohr-Coulomb joints (30 degrees). Reports block-steps per
// second and where the time goes (ms per step in each stage). Run:
//   build/release/dda_bench --benchmark_filter=PackedWall
#include <benchmark/benchmark.h>

#include <cmath>

#include "solver/step.hpp"
#include "solver/world.hpp"

namespace {

dda::World brick_wall(int n) {
  dda::Scene s;
  s.materials.push_back(dda::elastic_material("rock", 2700.0, 1e9, 0.25));
  s.joint_materials[0] = dda::JointMaterial{"default", 30.0, 0.0, 0.0};
  s.control.time_steps = {0.002};
  s.control.steps = 1 << 30;
  // A settling wall keeps ~7 open-close iterations a step (side contacts near the friction
  // limit); Shi's limit of 8 would cut steps now and then, which measures the cuts, not a step.
  s.control.max_open_close = 30;
  const int cols = static_cast<int>(std::ceil(std::sqrt(2.0 * n)));  // about square in metres
  const int rows = (n + cols - 1) / cols;
  // The same control in metres at every size: a step may move a vertex 1 cm (2 % of a
  // brick's height), so the search distance (2.5 x ratio x w0) is 2.5 cm. A fixed ratio
  // would let w0 = half the wall's width scale it: at 10000 bricks 0.01 w0 is 0.7 m, more
  // than a brick, and detection would pair every brick with its neighbours' neighbours.
  const double w0 = 0.5 * (cols + 2.0);  // the base is the widest thing in the scene
  s.control.max_displacement_ratio = 0.01 / w0;
  dda::BlockSpec base;
  base.vertices = {{-1.0, -1.0}, {cols + 1.0, -1.0}, {cols + 1.0, 0.0}, {-1.0, 0.0}};
  base.fixed = true;
  s.blocks.push_back(base);
  for (int i = 0; i < n; ++i) {
    const int r = i / cols, c = i % cols;
    const double x = c + (r % 2 ? 0.5 : 0.0), y = 0.5 * r;
    dda::BlockSpec b;
    b.vertices = {{x, y}, {x + 1.0, y}, {x + 1.0, y + 0.5}, {x, y + 0.5}};
    s.blocks.push_back(b);
  }
  (void)rows;
  return dda::make_world(s);
}

void BM_PackedWall(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  dda::World world = brick_wall(n);
  dda::StepWorkspace ws;
  dda::RunStats warmup;
  const int warmup_steps = n >= 10000 ? 1 : 5;  // contacts established
  for (int k = 0; k < warmup_steps; ++k) dda::advance_step(world, ws, warmup);
  dda::RunStats stats;
  const int factorisations_before = ws.solver.factorisations();
  for (auto _ : state) {
    const dda::StepOutcome outcome = dda::advance_step(world, ws, stats);
    if (!outcome.ok) state.SkipWithError(outcome.message.c_str());
  }
  const double steps = static_cast<double>(state.iterations());
  const dda::StageTimes& t = stats.stage_times;
  state.counters["block_steps_per_s"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["detect_ms"] = 1e3 * t.detect / steps;
  state.counters["assemble_ms"] = 1e3 * t.assemble / steps;
  state.counters["solve_ms"] = 1e3 * t.solve / steps;
  state.counters["contact_update_ms"] = 1e3 * t.contact_update / steps;
  state.counters["update_ms"] = 1e3 * t.update / steps;
  state.counters["open_close"] = static_cast<double>(stats.open_close_total) / steps;
  state.counters["contacts"] = stats.contacts_final;
  state.counters["factorisations"] = (ws.solver.factorisations() - factorisations_before) / steps;
}
BENCHMARK(BM_PackedWall)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
// 10000 bricks: a step takes seconds (see README "Speed"), so a few steps only.
BENCHMARK(BM_PackedWall)->Arg(10000)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace
