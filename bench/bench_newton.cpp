// The step's Newton iteration, hand-written inside the open-close loop (solver/step.cpp)
// against KINSOL with SUNDIALS' KLU (verification/reference/kinsol_step.hpp), on the same step: a
// Mohr-Coulomb specimen on its plateau, pushed through a platen
// (tests/solver/test_material_coupling.cpp has the scene and checks that both find the same
// increments). Arg: dilation angle
// (10: non-associated, unsymmetric tangent; 30: associated). Run:
//   build/release/dda_bench --benchmark_filter=Newton
#include <benchmark/benchmark.h>

#include "solver/contact_detection.hpp"
#include "kinsol_step.hpp"
#include "solver/step.hpp"
#include "solver/world.hpp"

namespace {

struct Plateau {
  dda::World world;
  std::vector<dda::Contact> contacts;  // as the last step left them (modes carried)
};

// Fixed base, unit-square specimen (c 1 MPa, phi 30), platen pushed 1e-5 m a step by a pin,
// confined by 1 MPa; 150 static steps bring it onto its plateau.
Plateau plateau(double dilation) {
  dda::Scene s;
  s.gravity = dda::Vec2::Zero();
  s.control.time_steps = {0.01};
  s.control.steps = 1 << 30;
  s.control.dynamic_coefficient = 0.0;
  s.control.max_displacement_ratio = 0.01;
  s.control.rotation_update = dda::RotationUpdate::LocalFrame;  // Shi's T in both solvers
  s.joint_materials.push_back(dda::JointMaterial{"default", 0.0, 0.0, 0.0});
  s.materials.push_back(dda::elastic_material("rock", 20.0, 1e10, 0.25));
  dda::Material soil = dda::elastic_material("soil", 20.0, 1e10, 0.25);
  soil.parameters.model_parameters = dda::plastic_parameters<dda::MohrCoulombParameters>(1e6, 30.0, dilation);
  s.materials.push_back(soil);
  dda::BlockSpec base, specimen, platen;
  base.vertices = {{-1, -1}, {2, -1}, {2, 0}, {-1, 0}};
  base.fixed = true;
  specimen.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  specimen.material = 1;
  platen.vertices = {{0, 1}, {1, 1}, {1, 1.2}, {0, 1.2}};
  s.blocks = {base, specimen, platen};
  s.point_loads.push_back(dda::PointLoadSpec{dda::Vec2(0, 0.5), dda::Vec2(1e6, 0), 1});
  s.point_loads.push_back(dda::PointLoadSpec{dda::Vec2(1, 0.5), dda::Vec2(-1e6, 0), 1});
  s.pins.push_back(dda::PinSpec{dda::Vec2(0.5, 1.2), 2});
  Plateau p{dda::make_world(s), {}};
  dda::StepWorkspace ws;
  dda::RunStats stats;
  for (int k = 0; k < 150; ++k) {
    p.world.pins[0].anchor.y() -= 1e-5;
    dda::advance_step(p.world, ws, stats);
  }
  p.world.pins[0].anchor.y() -= 1e-5;
  p.contacts = p.world.contacts;
  return p;
}

void BM_NewtonHandWritten(benchmark::State& state) {
  const Plateau start = plateau(static_cast<double>(state.range(0)));
  long solves = 0;
  for (auto _ : state) {
    state.PauseTiming();
    dda::World world = start.world;
    dda::StepWorkspace ws;  // a fresh factorisation, as KINSOL's
    dda::RunStats stats;
    state.ResumeTiming();
    const dda::StepOutcome outcome = dda::advance_step(world, ws, stats);
    if (!outcome.ok) state.SkipWithError(outcome.message.c_str());
    solves += stats.iterations;
  }
  state.counters["solves"] = static_cast<double>(solves) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_NewtonHandWritten)->Arg(10)->Arg(30)->Unit(benchmark::kMicrosecond);

void BM_NewtonKinsol(benchmark::State& state) {
  const Plateau start = plateau(static_cast<double>(state.range(0)));
  dda::StepContext ctx;
  ctx.dt = 0.01;
  ctx.penalty = start.world.penalty;
  ctx.dynamic_coefficient = 0.0;
  long iterations = 0, residuals = 0;
  for (auto _ : state) {
    // Contact detection is part of the step in both: the hand-written step does it too.
    std::vector<dda::Contact> contacts = start.contacts;
    dda::detect_contacts(start.world, contacts);
    const dda::KinsolStepResult k = dda::solve_step_with_kinsol(start.world, contacts, ctx, 1e-3);
    if (!k.ok) state.SkipWithError(k.message.c_str());
    iterations += k.iterations;
    residuals += k.residual_evals;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["newton_iterations"] = static_cast<double>(iterations) / n;
  state.counters["residual_evals"] = static_cast<double>(residuals) / n;
}
BENCHMARK(BM_NewtonKinsol)->Arg(10)->Arg(30)->Unit(benchmark::kMicrosecond);

}  // namespace
