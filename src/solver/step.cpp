#include "solver/step.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "solver/assembly.hpp"
#include "solver/configuration_update.hpp"

namespace dda {
namespace {

// A cut step retries with dt scaled by 0.9 * allowed / moved, kept within [0.1, 0.9]:
// the step's motion is roughly proportional to dt, so one cut usually suffices.
constexpr double kCutSafety = 0.9;
constexpr double kCutMin = 0.1;
constexpr double kCutMax = 0.9;
// Below this share of the scheduled step the run is declared diverged.
constexpr double kSmallestStepShare = 1e-9;
// Times closer than this share of a step count as equal (end_time reached).
constexpr double kTimeRoundOff = 1e-9;

StepContext make_step_context(const World& world, double dt, int attempt) {
  StepContext ctx;
  ctx.dt = dt;
  ctx.scheduled_dt = scheduled_time_step(world);
  ctx.penalty = world.penalty;
  ctx.dynamic_coefficient = world.control.dynamic_coefficient;
  ctx.allowed_displacement = world.control.max_displacement_ratio * world.w0;
  ctx.attempt = attempt;
  return ctx;
}

std::string describe_failure(const World& world, const std::string& what) {
  std::ostringstream out;
  out << "step " << world.step + 1 << " (t = " << world.time << " s): " << what;
  return out.str();
}

}  // namespace

double scheduled_time_step(const World& world) {
  const std::vector<double>& list = world.control.time_steps;
  double dt = list[static_cast<std::size_t>(world.step) % list.size()];
  if (world.control.end_time) dt = std::min(dt, *world.control.end_time - world.time);
  return dt;
}

bool is_finished(const World& world) {
  const ControlSettings& c = world.control;
  if (c.steps) return world.step >= *c.steps;
  const double typical = *std::min_element(c.time_steps.begin(), c.time_steps.end());
  return world.time >= *c.end_time - kTimeRoundOff * typical;
}

StepOutcome advance_step(World& world, StepWorkspace& ws, RunStats& stats) {
  // 1. Choose dt and build the step context.
  double dt = scheduled_time_step(world);
  for (int attempt = 0;; ++attempt) {
    const StepContext ctx = make_step_context(world, dt, attempt);

    // 2. Contact detection: none yet (issue 3).
    // 3. Assemble and solve (the open-close loop will wrap this with contacts).
    assemble(world, ctx, ws.system);
    const std::optional<Eigen::VectorXd> d = ws.solver.solve(ws.system);
    ++stats.iterations;
    if (!d || !d->allFinite()) {
      return {false, describe_failure(world, "the global system could not be solved "
                                             "(not positive definite or not finite)")};
    }

    // 4. Displacement-ratio check: too large a motion cuts dt and redoes the step.
    const double moved = max_vertex_displacement(world, *d);
    if (moved > ctx.allowed_displacement) {
      ++stats.cut_steps;
      dt *= std::clamp(kCutSafety * ctx.allowed_displacement / moved, kCutMin, kCutMax);
      if (dt < kSmallestStepShare * ctx.scheduled_dt) {
        return {false, describe_failure(world, "time step cut below 1e-9 of the scheduled "
                                               "one; the motion does not settle")};
      }
      continue;
    }

    // 5. Configuration update by the chosen rotation treatment.
    update_configuration(world, *d);
    // 6. Strains, stresses and velocities.
    update_stresses(world);
    update_velocities(world, *d, ctx);
    world.time += ctx.dt;
    ++world.step;
    return {};
  }
}

}  // namespace dda
