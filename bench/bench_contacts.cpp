// One DDA step of a packed brick wall resting on a fixed base: N bricks 1 m x 0.5 m in
// running bond (bench/brick_wall.hpp), under gravity, with Mohr-Coulomb joints (30
// degrees). Reports block-steps per second and where the time goes (ms per step in each
// stage). The same wall of rigid bricks (3 unknowns a brick instead of 6,
// the rest of the scene unchanged) is measured beside it. Run:
//   build/release/dda_bench --benchmark_filter='PackedWall|SettledWall|RigidWall'
#include <benchmark/benchmark.h>

#include <cmath>

#include "brick_wall.hpp"
#include "solver/energy.hpp"
#include "solver/step.hpp"
#include "solver/world.hpp"

namespace {

// Rigid bricks keep the material's density and (for the "auto" penalty) its Young's modulus.
dda::World brick_wall(int n, bool rigid) {
  dda::Material rock = dda::elastic_material("rock", 2700.0, 1e9, 0.25);
  rock.rigid = rigid;
  return dda::make_world(dda::bench::brick_wall_scene(n, rock));
}

// How the wall is brought to where the measured steps start.
enum class Warmup {
  Plain,           // ordinary dynamic steps
  KineticDamping,  // the same steps, every velocity zeroed at each peak of kinetic energy
};

double kinetic_energy(const dda::World& world) {
  double e = 0.0;
  for (const dda::Block& b : world.blocks) e += dda::kinetic_energy(world, b);
  return e;
}

// Kinetic damping (Cundall's, as in dynamic relaxation): a free wall oscillates about its
// rest state with a period that grows with its height (about 0.07 s at 1000 bricks, 0.2 s
// at 10000), and the implicit steps damp it little, so ordinary steps leave the 10000-brick
// wall moving after 300 steps. Zeroing every velocity when the kinetic energy has passed a
// peak takes out the energy of the slowest mode at each half period: the 1000-brick wall is
// below 1e-8 of its potential energy in kinetic energy after ~40 steps, the 10000-brick one
// after ~150 (its open-close loop takes one iteration a step from about step 230 on). The
// bench only: a run never does this.
void warm_up(dda::World& world, dda::StepWorkspace& ws, int steps, Warmup how) {
  dda::RunStats stats;
  double last = 0.0;
  for (int k = 0; k < steps; ++k) {
    dda::advance_step(world, ws, stats);
    if (how != Warmup::KineticDamping) continue;
    const double now = kinetic_energy(world);
    if (now < last) {
      for (dda::Block& b : world.blocks) {
        b.velocity.setZero();
        b.local_strain_rate.setZero();
      }
      last = 0.0;
    } else {
      last = now;
    }
  }
}

// Steps of the wall after `warmup_steps` steps.
void run_wall(benchmark::State& state, int warmup_steps, bool rigid = false,
              Warmup how = Warmup::Plain) {
  const int n = static_cast<int>(state.range(0));
  dda::World world = brick_wall(n, rigid);
  dda::StepWorkspace ws;
  warm_up(world, ws, warmup_steps, how);
  dda::RunStats stats;
  const dda::LinearSolveStats before = ws.solver.stats();
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
  const dda::LinearSolveStats& after = ws.solver.stats();
  state.counters["factorisations"] = (after.factorisations - before.factorisations) / steps;
  state.counters["analyses"] = (after.analyses - before.analyses) / steps;
  state.counters["modifications"] = (after.modifications - before.modifications) / steps;
  state.counters["cg_iterations"] =
      static_cast<double>(after.cg_iterations - before.cg_iterations) / steps;
  state.counters["solves"] = static_cast<double>(stats.iterations) / steps;
  // At rest means this far below 1e-7 (the settled wall's criterion) after the measured steps.
  const dda::EnergyTotals e = dda::scene_energy(world);
  state.counters["kinetic_over_potential"] = e.kinetic / std::abs(e.potential);
}

// A wall just built: its contacts are established (5 steps; 1 at 10000 bricks), it is
// still settling.
void BM_PackedWall(benchmark::State& state) { run_wall(state, state.range(0) >= 10000 ? 1 : 5); }
BENCHMARK(BM_PackedWall)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
// 10000 bricks: a step takes seconds (see README "Speed"), so a few steps only.
BENCHMARK(BM_PackedWall)->Arg(10000)->Iterations(3)->Unit(benchmark::kMillisecond);

// The settled wall: at rest, its kinetic energy far below 1e-7 of its potential
// energy (the counter kinetic_over_potential says how far). The targets: 1 ms a step
// at 100 bricks, 15 ms at 1000, 1 s at 10000. Brought to rest by 300 steps with kinetic
// damping (warm_up above): about 5 s at 1000 bricks and 6 to 7 minutes at 10000 (whose
// open-close loop takes one iteration a step from about step 230 on), so run
// that one alone, --benchmark_filter='SettledWall/10000'. (Formerly the warm-up was
// 300 plain steps, after which the 1000-brick wall still moved at ~1e-7 of its potential
// energy and took 1.2 solves a step, and the 10000-brick wall was still settling.)
constexpr int kSettleSteps = 300;
void BM_SettledWall(benchmark::State& state) {
  run_wall(state, kSettleSteps, false, Warmup::KineticDamping);
}
BENCHMARK(BM_SettledWall)->Arg(100)->Arg(1000)->Iterations(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SettledWall)->Arg(10000)->Iterations(10)->Unit(benchmark::kMillisecond);

// The same two walls of rigid bricks: 3 unknowns a brick, so the global
// system has half the unknowns and a quarter of the entries of the deformable wall's.
void BM_PackedRigidWall(benchmark::State& state) { run_wall(state, 5, true); }
BENCHMARK(BM_PackedRigidWall)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
void BM_SettledRigidWall(benchmark::State& state) {
  run_wall(state, kSettleSteps, true, Warmup::KineticDamping);
}
BENCHMARK(BM_SettledRigidWall)->Arg(100)->Arg(1000)->Iterations(100)->Unit(benchmark::kMillisecond);

}  // namespace
