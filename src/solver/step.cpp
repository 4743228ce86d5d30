#include "solver/step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "solver/assembly.hpp"
#include "solver/configuration_update.hpp"
#include "solver/contact_assembly.hpp"
#include "solver/contact_detection.hpp"
#include "solver/energy.hpp"
#include "solver/material_coupling.hpp"

namespace dda {
namespace {

// A step whose motion exceeds the displacement ratio retries with dt scaled by
// 0.9 * allowed / moved, kept within [0.1, 0.9]: the motion is roughly proportional to dt,
// so one cut usually suffices.
constexpr double kCutSafety = 0.9;
constexpr double kCutMin = 0.1;
constexpr double kCutMax = 0.9;
// Shi's cut when the open-close loop does not settle, or a contact penetrates too far.
constexpr double kContactCut = 0.3;
// Penetration cuts per step before the run stops: six cuts by 0.3 bring dt to 7e-4 of the
// scheduled step, where an impact's penetration (which shrinks with dt) is long cured; what
// is left is a static penetration, which no cut cures.
constexpr int kPenetrationCuts = 6;
// Below this share of the scheduled step the run is declared diverged.
constexpr double kSmallestStepShare = 1e-9;
// Times closer than this share of a step count as equal (end_time reached).
constexpr double kTimeRoundOff = 1e-9;

// finite_rotation iterates each block's secant angle r* to the step's own r0. A secant
// column at r* instead of r0 moves a point at distance l from the reference point by about
// l |r0| |r0 - r*| / 2 off the exact rotation (the column's derivative at small angles is
// -I/2): the iteration stops when that is below this share of w0 for every block, e.g.
// 1e-12 x 5 m per step on the paper's swinging octagon (5e-9 m over its 5000 steps). A
// block that barely turns is done after one solve.
constexpr double kSecantDisplacementShare = 1e-12;
// A scene with plastic blocks allows this many loop iterations beyond max_open_close: the
// loop is then also the Newton iteration of the blocks' material equilibrium (quadratic
// with associated flow, linear with non-associated; solver/material_coupling.hpp).
constexpr int kExtraNewtonIterations = 20;

StepContext make_step_context(const World& world, double dt) {
  StepContext ctx;
  ctx.dt = dt;
  ctx.penalty = world.penalty;
  ctx.dynamic_coefficient = world.control.dynamic_coefficient;
  ctx.allowed_displacement = world.control.max_displacement_ratio * world.w0;
  return ctx;
}

// The treatments that change T inside the step: sin_variable uses Cheng and Zhang's column
// with the last step's r0 (paper Eq. 11); finite_rotation the secant column at r* (starting
// from the last step's r0, then following the step's own). The rest keep Shi's column.
bool changes_t(RotationUpdate u) {
  return u == RotationUpdate::SinVariable || u == RotationUpdate::FiniteRotation;
}

void set_rotation_columns(const World& world, const std::vector<double>& angles,
                          StepContext& ctx) {
  ctx.rotation_columns.assign(world.blocks.size(), quarter_turn());
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    if (world.blocks[i].fixed) continue;
    ctx.rotation_columns[i] = world.control.rotation_update == RotationUpdate::SinVariable
                                  ? sine_rotation_column(angles[i])
                                  : secant_rotation_column(angles[i]);
  }
}

std::vector<double> last_rotation_increments(const World& world) {
  std::vector<double> angles(world.blocks.size(), 0.0);
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    angles[i] = world.blocks[i].last_rotation_increment;
  }
  return angles;
}

// finite_rotation: moves every block's secant angle to the r0 just solved; returns how many
// were further from it than the tolerance (0: the step's T is consistent with its r0).
int follow_secant_angles(const World& world, const Eigen::VectorXd& d,
                         std::vector<double>& angles) {
  const double tolerance = kSecantDisplacementShare * world.w0;
  int moved = 0;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed) continue;
    const double r0 = d[b.first_dof + kR0];
    double reach = 0.0;  // farthest vertex from the reference point
    for (const Vec2& v : b.vertices) reach = std::max(reach, (v - b.moments.centroid).norm());
    if (0.5 * reach * std::abs(r0) * std::abs(r0 - angles[i]) > tolerance) ++moved;
    angles[i] = r0;
  }
  return moved;
}

// sin_variable solves for sin r0 in the rotation slot; the stages after the loop want r0.
void sine_unknowns_to_angles(const World& world, Eigen::VectorXd& d) {
  for (const Block& b : world.blocks) {
    if (!b.fixed) d[b.first_dof + kR0] = std::asin(std::clamp(d[b.first_dof + kR0], -1.0, 1.0));
  }
}

std::string describe_failure(const World& world, const std::string& what) {
  std::ostringstream out;
  out << "step " << world.step + 1 << " (t = " << world.time << " s): " << what;
  return out.str();
}

int closed_contacts(const std::vector<Contact>& contacts) {
  return static_cast<int>(std::count_if(contacts.begin(), contacts.end(), [](const Contact& c) {
    return c.mode != ContactMode::Open;
  }));
}

void count_step(const StepWorkspace& ws, int open_close, RunStats& stats) {
  stats.open_close_total += open_close;
  stats.open_close_max = std::max(stats.open_close_max, open_close);
  const int closed = closed_contacts(ws.contacts);
  stats.contacts_total += closed;
  stats.contacts_max = std::max(stats.contacts_max, closed);
  stats.contacts_final = closed;
  stats.deepest_penetration = std::max(stats.deepest_penetration, max_penetration(ws.contacts));
  for (const Contact& c : ws.contacts) {
    stats.largest_normal_force = std::max(stats.largest_normal_force, c.normal_force);
  }
}

// Adds the time since construction (or the last lap) to a stage's total.
class StageClock {
 public:
  StageClock() : last_(std::chrono::steady_clock::now()) {}
  void lap(double& total) {
    const auto now = std::chrono::steady_clock::now();
    total += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_;
};

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
  StageTimes& times = stats.stage_times;
  StageClock clock;
  // 1. Choose dt.
  const double scheduled_dt = scheduled_time_step(world);
  double dt = scheduled_dt;
  // 2. Contact detection on the configuration at the step's start; contacts keep the state
  //    they had last step. A redone attempt starts again from these.
  detect_contacts(world, ws.contacts);
  const std::vector<Contact> contacts_at_start = ws.contacts;
  clock.lap(times.detect);
  int penetration_cuts = 0;

  for (;;) {
    if (dt < kSmallestStepShare * scheduled_dt) {
      return {false, describe_failure(world, "time step cut below 1e-9 of the scheduled one; "
                                             "the contacts or the motion do not settle")};
    }
    StepContext ctx = make_step_context(world, dt);
    const RotationUpdate treatment = world.control.rotation_update;
    std::vector<double> angles;  // per block: the angle inside T's rotation column
    if (changes_t(treatment)) {
      angles = last_rotation_increments(world);
      set_rotation_columns(world, angles, ctx);
    }
    const bool plastic = has_plastic_blocks(world);
    if (plastic) ctx.material_terms = start_linearization(world);
    const int iteration_limit =
        world.control.max_open_close + (plastic ? kExtraNewtonIterations : 0);
    ws.contacts = contacts_at_start;  // states as they entered the step, no changes counted

    // 3. Open-close loop: assemble, solve, let every contact choose its next mode, until
    //    no contact changes (and, for finite_rotation, until each block's secant angle is its
    //    own r0). The first iteration factorises; later ones update the factor by the springs
    //    of the contacts that changed (CholmodSolver::solve_modified), unless T changed.
    assemble(world, ctx, ws.block_terms);
    Eigen::VectorXd d;
    int open_close = 0;
    int changed = 0;
    int held_in_tension = 0;
    int secants_moved = 0;
    MaterialFollowUp materials;
    bool factor_stale = false;
    do {
      ws.system = ws.block_terms;
      add_contact_terms(world, ws.contacts, ctx, ws.system);
      clock.lap(times.assemble);
      // A non-associated plastic block makes the system unsymmetric: KLU then, and CHOLMOD's
      // factor (which no longer follows the contact springs) is rebuilt when next used.
      const bool unsymmetric = plastic && any_unsymmetric(ctx.material_terms);
      const bool refactor = open_close == 0 || secants_moved > 0 || materials.unconverged > 0 ||
                            factor_stale;
      const std::optional<Eigen::VectorXd> solved =
          unsymmetric ? solve_klu(ws.system)
          : refactor  ? ws.solver.solve(ws.system)
                      : ws.solver.solve_modified(ws.system, ws.springs_added, ws.springs_removed);
      factor_stale = unsymmetric;
      clock.lap(times.solve);
      ++stats.iterations;
      ++open_close;
      if (!solved || !solved->allFinite()) {
        return {false, describe_failure(world, "the global system could not be solved "
                                               "(not positive definite or not finite)")};
      }
      d = *solved;
      const std::vector<SpringState> before = spring_states(ws.contacts);
      const ContactUpdate contact_update = update_contact_modes(world, ws.contacts, d, ctx);
      changed = contact_update.changed;
      held_in_tension = contact_update.held_in_tension;
      spring_changes(world, ws.contacts, before, ctx, ws.springs_added, ws.springs_removed);
      if (treatment == RotationUpdate::FiniteRotation) {
        secants_moved = follow_secant_angles(world, d, angles);
        if (secants_moved > 0) set_rotation_columns(world, angles, ctx);
      }
      if (plastic) {
        materials = follow_materials(world, d, ctx.material_terms);
        if (materials.failed) break;
      }
      if (secants_moved > 0 || materials.unconverged > 0) assemble(world, ctx, ws.block_terms);
      clock.lap(times.contact_update);
    } while ((changed > 0 || secants_moved > 0 || materials.unconverged > 0) &&
             open_close < iteration_limit);
    if (materials.failed) {
      // A return map that fails is cured by a smaller strain increment: cut by the
      // material's own suggestion, within Shi's usual range.
      ++stats.cut_steps;
      ++stats.cuts_for_material;
      dt *= std::clamp(materials.suggested_fraction, kCutMin, kCutMax);
      continue;
    }
    if (treatment == RotationUpdate::SinVariable) sine_unknowns_to_angles(world, d);
    if (changed > 0 || held_in_tension > 0 || secants_moved > 0 || materials.unconverged > 0) {
      ++stats.cut_steps;
      ++stats.cuts_for_open_close;
      dt *= kContactCut;
      continue;
    }

    // 4. Displacement-ratio check: too large a motion cuts dt and redoes the step.
    const double moved = max_vertex_displacement(world, d);
    if (moved > ctx.allowed_displacement) {
      ++stats.cut_steps;
      ++stats.cuts_for_displacement;
      dt *= std::clamp(kCutSafety * ctx.allowed_displacement / moved, kCutMin, kCutMax);
      continue;
    }
    //    Penetration check: an impact is cut. The penalty is never changed: raising it while
    //    contacts are loaded put energy into them, and a run must not change its model
    //    silently. A penetration that cutting does not cure (a static load the penalty
    //    cannot carry within allowed_penetration) ends the run with a message that says so.
    if (max_penetration(ws.contacts) > world.allowed_penetration) {
      ++stats.cut_steps;
      ++stats.cuts_for_penetration;
      if (++penetration_cuts > kPenetrationCuts) {
        std::ostringstream what;
        what << "contacts penetrate " << max_penetration(ws.contacts)
             << " m, more than allowed_penetration " << world.allowed_penetration << " m, even at "
             << dt / scheduled_dt << " of the scheduled time step: the load needs a stiffer "
             << "contact; raise control.penalty (now " << world.penalty
             << " N/m) or control.allowed_penetration";
        return {false, describe_failure(world, what.str())};
      }
      dt *= kContactCut;
      continue;
    }

    // The energy account's terms of this step, on the step's own T and contacts.
    const StepEnergy energy_terms = step_energy(world, ws.contacts, d, ctx);
    // 5. Configuration update by the chosen rotation treatment.
    update_configuration(world, d);
    // 6. Strains, stresses and velocities.
    update_stresses(world);
    update_velocities(world, d, ctx);
    clock.lap(times.update);
    world.time += ctx.dt;
    ++world.step;
    commit_step_energy(world, energy_terms, ws.contacts, d, ctx.penalty);
    count_step(ws, open_close, stats);
    // The energy guard: a step that leaves the run with more energy than loads put in
    // (beyond the tolerance) ends it; the step is kept, so the output shows it.
    std::string gained = energy_guard_message(world, energy_terms, world.control.energy_tolerance);
    if (!gained.empty()) return {false, std::move(gained)};
    return {};
  }
}

}  // namespace dda
