#include "solver/step.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "contact/narrow_phase.hpp"
#include "kinematics/polygon.hpp"
#include "solver/assembly.hpp"
#include "solver/configuration_update.hpp"
#include "solver/contact_assembly.hpp"
#include "solver/open_close_modes.hpp"
#include "solver/base_motion.hpp"
#include "solver/contact_detection.hpp"
#include "solver/contact_newton.hpp"
#include "solver/energy.hpp"
#include "solver/force_element.hpp"
#include "solver/material_coupling.hpp"
#include "solver/rotation/rotation_columns.hpp"
#include "solver/rotation/treatment.hpp"
#include "solver/schedule.hpp"
#include "solver/step_solve.hpp"

namespace dda {
namespace {

// A step whose motion exceeds a block's step limit retries with dt scaled by
// 0.9 / (the largest share of its limit a block moved), kept within [0.1, 0.9]: the motion
// is roughly proportional to dt, so one cut usually suffices.
constexpr double kCutSafety = 0.9;
constexpr double kCutMin = 0.1;
constexpr double kCutMax = 0.9;
// Shi's cut when the open-close loop does not settle, or a contact penetrates too far.
constexpr double kContactCut = 0.3;
// Penetration cuts per step before the run stops: six cuts by 0.3 bring dt to 7e-4 of the
// scheduled step, where what a step adds to an impact's penetration (which shrinks with dt)
// is long below kDeepeningShare; what is left is a static penetration, which no cut cures.
constexpr int kPenetrationCuts = 6;
// The same limit on a step that starts short: a penetration cut needed when dt is already this
// share of the schedule (six contact cuts' worth) ends the run too. The remembered step size
// would otherwise let a load the penalty cannot carry creep down a few cuts a step, each step
// accepted a little shorter, until the step vanished with no word of the penetration.
constexpr double kPenetrationFloor =
    kContactCut * kContactCut * kContactCut * kContactCut * kContactCut * kContactCut;
// An impact whose kinetic energy the contact spring cannot take within the allowed
// penetration (normal speed v, mass m: v sqrt(m / penalty) deeper than the allowance) is
// not cured by cutting dt: once the inertia term 2m/dt^2 outgrows the penalty, a shorter
// step changes the block's speed less, the vertex goes on at v, and the augmented
// multipliers, which move it only against that term, lose their grip. (In the 300-polygon
// hopper a polygon 0.12 m across hit a neighbour at 5.6 m/s: about 1.8e-4 m of spring
// travel against an allowance of 5e-5 m; cut after cut down to 1e-6 s, the run stopped.)
// So a contact already deeper than its allowance cuts the step only if the step deepened it
// by more than this share of the allowance: over the impact's steps the spring stops the
// block and throws it back (no multiplier acts in steps that short: augment_multipliers).
constexpr double kDeepeningShare = 0.5;
// ... and in any case beyond this many allowances: at 4e-4 of the smaller block's size, ten
// of them are 0.4 % of it, far inside the block still, and the impact above stays within
// them up to about 10 m/s. A load the penalty cannot carry in a dynamic run creeps towards it
// a step at a time and then ends the run with the message that says so.
constexpr double kPenetrationHardShare = 10.0;
// An open contact whose vertex, placed by the configuration update itself, ends the step
// deeper than this share of the allowed penetration inside the other block cuts the step
// (CutReason::Overshoot). The open-close loop judges a gap by its linearisation, which
// misses s theta when the vertex moves a distance s along an edge that turns by theta; a
// vertex found inside next step would bring p g^2 / 2 that no force put there (a 48-block
// pack gained 96 J/m at once from a corner that slid 9 mm along a turning edge, the
// linearised gap 78 um open, the true one 62 um closed). The error falls as dt^2; the
// share bounds what one such contact can bring to p (0.01 a)^2 / 2.
constexpr double kOvershootShare = 0.01;
// Below this share of the scheduled step the run is declared diverged.
constexpr double kSmallestStepShare = 1e-9;
// The step size that remembers (World::step_size, remember_step): after a cut, each step that
// succeeds at the remembered size lets the next try up to this factor longer, until the
// schedule is reached. 1.2 (ODE step controllers cap growth at 1.5 to 5,
// but they have an error estimate to aim with, and a failed DDA attempt costs a whole solve)
// brings a contact cut (0.3) back to the schedule in 7 steps and Shi's smallest cut (0.1) in
// 13, so a passing event costs a handful of short steps; were the cause to persist, a growth
// that fails again loses one attempt in about 7 accepted steps rather than one in each.
constexpr double kStepGrowth = 1.2;

// Penetration control at a fixed penalty (Lin, Amadei et al. 1996): when the settled loop
// leaves a contact deeper than the allowed penetration, every closed contact deeper than
// kAugmentTargetShare of it adds the excess to its multiplier (ContactState::rest_shift) and
// the loop goes on with the same matrix (a back-substitution), up to
// control.max_augmentations rounds a step (allowed beyond max_open_close); what they do not
// cure, cutting dt does. The multiplier stays while the contact is closed, so a load the
// penalty alone would carry at g is carried at about half the allowed penetration; aiming
// at half, not at zero, keeps the contact clear of its opening threshold (it opens by its
// geometric gap and then drops the multiplier).
constexpr double kAugmentTargetShare = 0.5;
// A scene with plastic blocks allows this many loop iterations beyond max_open_close: the
// loop is then also the Newton iteration of the blocks' material equilibrium (quadratic
// with associated flow, linear with non-associated; solver/material_coupling.hpp).
constexpr int kExtraNewtonIterations = 20;
// The converged contact solver's iterations a step before it is cut (at least
// max_open_close): a semismooth Newton iteration with a line search does not cycle, but a
// box of 150 tumbling blocks may need more than Shi's 8 solves to find every contact's mode.
constexpr int kNewtonIterations = 30;
// The converged solver's cycle detection and its way out. A cycle of four solves (two
// contacts of a tumbling square in a box of ten, each closing the other's gap in turn, the
// line search taking every step whole) ran to the limit and cut the step, where the three
// solves the detection then looked back over could not see it. Once a mismatch repeats one
// of the last kCycleWindow solves', the iterate moves kCycleDamping of the way the line search
// says (relaxation: the next modes are read between the cycle's states).
constexpr std::size_t kCycleWindow = 8;
// Two solves' mismatches are the same when their counts are and their largest mismatches
// agree to this share: a cycle's states come back with round-off (in the hopper, three
// solves repeating 570099.2229319, 406798.7983620, 102502.2508638 to 1e-12 relative ran to
// the limit unseen and cut the step: 29 open-close cuts in its first 1.5 s, 12 with this).
constexpr double kCycleMatch = 1e-9;
constexpr double kCycleDamping = 0.5;
// The most energy, as a share of the run's energy scale, that the springs of contacts solved
// open and ending inside may hold when an attempt is accepted unconverged (a cycle or the
// limit with no closed contact's normal force undecided): 1e-5, a hundredth of the hard
// cases' energy tolerance, so that a hundred such acceptances stay within it.
constexpr double kAcceptedInsideShare = 1e-5;
// How often an attempt may hold pulling contacts open (ContactNewton::hold_open_pulling),
// and the iterations each time earns. On the 1965-block slope's consolidation and its
// failing strength-reduction trial, 1 to 3 rounds of 5 or 10 iterations gave the same
// cuts and times to within their chaotic spread; an attempt that wanders with hundreds of
// contacts out of their mode is not saved by holding, and each round adds to its cost.
constexpr int kHoldOpenRounds = 2;
constexpr int kHeldOpenIterations = 5;

// An attempt's settings; `water_forces` (the step's) and `terms` (the attempt's loop terms)
// outlive it.
StepContext make_step_context(const World& world, double dt,
                              const std::vector<BlockForce>& water_forces, const LoopTerms& terms) {
  StepContext ctx;
  ctx.dt = dt;
  ctx.penalty = world.penalty;
  ctx.dynamic_coefficient = world.control.dynamic_coefficient;
  if (world.base_motion) {
    ctx.base_acceleration = mean_base_acceleration(*world.base_motion, world.time, world.time + dt);
  }
  ctx.water_forces = water_forces;
  ctx.loop = &terms;
  return ctx;
}

// The rotating-frame inertia's spins (kinematics/rotating_inertia.hpp), with the
// pseudo-rigid body's inertia (which needs a block frame), in dynamic runs (a static step
// starts every block from rest: no velocity, no quadratic velocity terms). At the step's
// start they are taken from the velocities carried in; finite_rotation then follows them to
// the step's own mean rates, like its secant angles (its follow_solve,
// solver/rotation/secant_column.cpp). Rigid blocks have no strain to stretch.
bool has_rotating_inertia(const World& world, const StepContext& ctx) {
  return world.pseudo_rigid && ctx.dynamic_coefficient > 0.0;
}

void start_spins(const World& world, const StepContext& ctx, LoopTerms& terms) {
  terms.spins.assign(world.blocks.size(), Spin{});
  const double k = ctx.dynamic_coefficient;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed || b.rigid) continue;
    terms.spins[i] = Spin{k * b.velocity[kR0], k * b.local_strain_rate};
  }
}

std::string describe_failure(const World& world, const std::string& what) {
  std::ostringstream out;
  out << "step " << world.step + 1 << " (t = " << world.time << " s): " << what;
  return out.str();
}

// When a deformable block has been squeezed to a hundredth of its area or less, the likely
// reason a solve broke down (its mass and stiffness vanish with its area): said with it.
std::string crushed_block_note(const World& world) {
  double smallest = 0.01;
  std::optional<std::size_t> which;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed || b.rigid || !(b.initial_area > 0.0)) continue;
    const double share = b.moments.area / b.initial_area;
    if (share < smallest) {
      smallest = share;
      which = i;
    }
  }
  if (!which) return "";
  std::ostringstream out;
  out << "; block " << *which << " has been squeezed to " << smallest
      << " of its area: its material is far too soft for its load";
  return out.str();
}

int closed_contacts(const std::vector<Contact>& contacts) {
  return static_cast<int>(std::count_if(contacts.begin(), contacts.end(), [](const Contact& c) {
    return c.state.mode != ContactMode::Open;
  }));
}

void count_step(const World& world, int open_close, RunStats& stats) {
  stats.open_close_total += open_close;
  stats.open_close_max = std::max(stats.open_close_max, open_close);
  const int closed = closed_contacts(world.contacts);
  stats.contacts_total += closed;
  stats.contacts_max = std::max(stats.contacts_max, closed);
  stats.contacts_final = closed;
  stats.deepest_penetration = std::max(stats.deepest_penetration, max_penetration(world.contacts));
  for (const Contact& c : world.contacts) {
    stats.largest_normal_force = std::max(stats.largest_normal_force, c.state.normal_force);
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

double time_step_to_try(const World& world) {
  const double scheduled = scheduled_time_step(world);
  const double remembered = world.step_size.next;
  return remembered > 0.0 ? std::min(scheduled, remembered) : scheduled;
}

bool is_finished(const World& world) {
  const ControlSettings& c = world.control;
  if (c.steps) return world.step >= *c.steps;
  // A run takes at least one step: an end time within round-off of the start (the reader
  // keeps it at least 1e-9 s) is one step of that length, not none.
  if (world.step == 0) return false;
  return reached_time(world.time, *c.end_time, c.time_steps);
}

namespace {

// What one pass of the open-close loop (stage 3) ended with.
struct LoopResult {
  Eigen::VectorXd d;          // the step's increments
  int iterations = 0;         // assemble + solve passes
  bool solved = true;         // false: the global system could not be solved
  std::optional<CutReason> unsettled;  // the loop did not settle: the reason to cut
  double material_fraction = 1.0;      // with CutReason::Material: the return's suggestion
  std::string material_reason;         // with CutReason::Material: the block and why it failed
  int augmentations = 0;               // augmented-Lagrangian rounds (penetration control)
};

// The ledger of the factor's springs follows what the solver did with the factor.
void follow_factor(const World& world, StepWorkspace& ws) {
  switch (ws.solver.last_path()) {
    case CholmodSolver::Path::Factorised: ws.factor_springs.record_all(world.contacts); break;
    case CholmodSolver::Path::Modified: ws.factor_springs.commit(); break;
    case CholmodSolver::Path::Reused: break;  // no springs changed
  }
}

// What both contact solvers set up before their first solve: the treatment's start (the
// rotation columns of the treatments that change T, and their angles), the plastic blocks'
// elastic predictor, the rotating inertia's spins, the force elements' modes (bolts).
struct LoopStart {
  RotationIterate rotation;
  bool plastic = false;
  bool spinning = false;
};

LoopStart start_loop(const World& world, const StepContext& ctx, LoopTerms& terms) {
  LoopStart start;
  treatment_of(world).start_step(world, ctx, terms, start.rotation);
  start.plastic = has_plastic_blocks(world);
  if (start.plastic) terms.material_terms = start_linearization(world);
  start.spinning = has_rotating_inertia(world, ctx);
  if (start.spinning) start_spins(world, ctx, terms);
  start_element_modes(world, terms);
  return start;
}

// One assemble-and-solve pass of either contact solver: the block terms plus the contacts'
// springs in their present modes. A non-associated plastic block makes the system
// unsymmetric: KLU then, fresh each time; CHOLMOD's kept factor is left as it was
// (FactorSprings still describes it), and serves again when the system is symmetric.
// Otherwise the kept factor (from this step or an earlier one) is brought to the present
// springs by rank-one updates when that is cheap, and CG on it makes up the rest (T,
// geometry, material tangents); CholmodSolver factorises when either would cost more.
// (The solvers see only a rigid block's u0, v0, r0; solve_system, step_solve.hpp.)
// nullopt when the system could not be solved or its answer is not finite.
std::optional<Eigen::VectorXd> assemble_and_solve(World& world, StepWorkspace& ws,
                                                  const StepContext& ctx, bool unsymmetric,
                                                  RunStats& stats, StageClock& clock) {
  ws.system = ws.block_terms;
  add_contact_terms(world, world.contacts, ctx, ws.system);
  clock.lap(stats.stage_times.assemble);
  std::optional<Eigen::VectorXd> solved;
  if (unsymmetric) {
    solved = solve_system(ws, SolvePath::Klu);
  } else {
    ws.factor_springs.differences(world, world.contacts, ctx, ws.springs_added, ws.springs_removed);
    solved = solve_system(ws, SolvePath::Modify);
    if (solved) follow_factor(world, ws);
  }
  clock.lap(stats.stage_times.solve);
  ++stats.iterations;
  if (solved && !solved->allFinite()) solved.reset();
  return solved;
}

// Whether the step's system is unsymmetric: a plastic block's non-associated flow.
bool unsymmetric_system(const LoopTerms& terms, bool plastic) {
  return plastic && any_unsymmetric(terms.material_terms);
}

// One solve of either contact loop, counted in r; nullopt, with r marked unsolved, when the
// system could not be solved.
std::optional<Eigen::VectorXd> solve_iteration(World& world, StepWorkspace& ws,
                                               const StepContext& ctx, bool unsymmetric,
                                               LoopResult& r, RunStats& stats, StageClock& clock) {
  std::optional<Eigen::VectorXd> solved = assemble_and_solve(world, ws, ctx, unsymmetric, stats, clock);
  ++r.iterations;
  if (!solved) r.solved = false;
  return solved;
}

// One iterate of the open-close loop: what its solve changed. The loop reads from it alone
// whether it has settled, whether another solve would see another system, and its verdict.
struct OpenCloseIterate {
  ContactUpdate contacts;      // modes changed; contacts held closed in tension
  int rotation_moved = 0;      // blocks whose T or spin is off the answer (follow_solve)
  MaterialFollowUp materials;  // plastic blocks whose Newton iteration has not converged
  int element_modes = 0;       // force elements (bolts) whose mode changed
  int augmented = 0;           // contacts whose multiplier grew after this solve

  // The answer agrees with the system it was solved from: no contact changed mode or is held
  // in tension, and T, the spins, the plastic blocks' linearisation and the bolts' modes
  // follow it.
  bool settled() const {
    return contacts.changed == 0 && contacts.held_in_tension == 0 && rotation_moved == 0 &&
           materials.unconverged == 0 && element_modes == 0;
  }
  // The next solve would see another system. (A contact held in tension changes none: the
  // loop stops there, and its verdict cuts the step.)
  bool system_changed() const {
    return contacts.changed > 0 || rotation_moved > 0 || materials.unconverged > 0 ||
           element_modes > 0 || augmented > 0;
  }
  // The verdict on the iterate the loop ended with: accepted when settled with no multiplier
  // grown after its solve, else cut.
  std::optional<CutReason> verdict() const {
    if (settled() && augmented == 0) return std::nullopt;
    return CutReason::OpenClose;
  }
};

// 3. The open-close loop: assemble, solve, let every contact choose its next mode, until no
//    contact changes (and, for finite_rotation, until each block's secant angle is its own
//    r0; for plastic blocks, until their Newton iteration has converged). Every
//    iteration solves with the factor kept from earlier iterations and steps, updated by the
//    springs of the contacts whose mode changed since it was made, and CG for the rest
//    (CholmodSolver::solve_modified); it is refactorised when that costs less.
LoopResult solve_open_close(World& world, StepWorkspace& ws, const StepContext& ctx,
                            LoopTerms& terms, RunStats& stats, StageClock& clock) {
  StageTimes& times = stats.stage_times;
  const RotationTreatment& treatment = treatment_of(world);
  LoopStart start = start_loop(world, ctx, terms);
  const bool plastic = start.plastic, spinning = start.spinning;
  // (Each augmented-Lagrangian round used adds one more: the rounds are allowed beyond it.)
  const int iteration_limit = world.control.max_open_close + (plastic ? kExtraNewtonIterations : 0);

  assemble(world, ctx, ws.block_terms);
  LoopResult r;
  // Whether the block terms were assembled with spins followed from an iterate (not those
  // carried into the step): only then must the answer's own spins agree with them
  // (follow_spins). The first solve's, at the carried rates, is a consistent step too.
  bool followed_spins_assembled = false;
  OpenCloseIterate it;
  do {
    it = OpenCloseIterate{};
    const std::optional<Eigen::VectorXd> solved =
        solve_iteration(world, ws, ctx, unsymmetric_system(terms, plastic), r, stats, clock);
    if (!solved) return r;
    r.d = *solved;
    it.contacts = update_contact_modes(world, world.contacts, r.d, ctx);
    // T and the spins follow the answer where the treatment iterates them.
    it.rotation_moved =
        treatment.follow_solve(world, r.d, ctx, terms, start.rotation,
                               {spinning, plastic && followed_spins_assembled, nullptr})
            .moved;
    if (plastic) {
      it.materials = follow_materials(world, r.d, terms.material_terms);
      if (it.materials.failed) {
        r.unsettled = CutReason::Material;
        r.material_fraction = it.materials.suggested_fraction;
        r.material_reason = it.materials.reason;
        return r;
      }
    }
    it.element_modes = follow_element_modes(world, r.d, ctx, terms);
    if (it.rotation_moved > 0 || it.materials.unconverged > 0 || it.element_modes > 0) {
      assemble(world, ctx, ws.block_terms);
      followed_spins_assembled = spinning;
    }
    if (it.settled() && r.augmentations < world.control.max_augmentations &&
        deepest_penetration_share(world.contacts) > 1.0) {
      it.augmented = augment_multipliers(world, world.contacts, kAugmentTargetShare, ctx);
      if (it.augmented > 0) ++r.augmentations;
    }
    clock.lap(times.contact_update);
  } while (it.system_changed() && r.iterations < iteration_limit + r.augmentations);
  treatment.finish_unknowns(world, r.d);
  r.unsettled = it.verdict();
  return r;
}

// The converged solver's iterate between two solves (as SapSolver::SolveWithGuess keeps
// its own): the increments it stands at, and what the loop remembers of its solves to see
// progress, a cycle and its limit.
struct NewtonIterate {
  Eigen::VectorXd d;  // six slots per free block
  int limit = 0;      // solves before the step is cut; bond breaks, augmentations and holds add
  int holds = 0;      // times contacts were held open (hold_open_pulling)
  int fewest_mismatched = std::numeric_limits<int>::max();
  // Whether the block terms hold spins followed from an iterate (solve_open_close says why).
  bool followed_spins_assembled = false;
  // The last solves' (mismatched, largest): a cycle of up to kCycleWindow solves is seen.
  std::array<std::pair<int, double>, kCycleWindow> recent{};

  // Whether a solve's mismatch repeats one of the last kCycleWindow solves' (kCycleMatch).
  bool cycling(const NewtonCheck& check) const {
    const std::pair<int, double> signature{check.mismatched, check.largest_mismatch};
    const auto same = [&signature](const std::pair<int, double>& seen) {
      return seen.first == signature.first &&
             std::abs(seen.second - signature.second) <= kCycleMatch * std::abs(signature.second);
    };
    return check.mismatched > 0 && std::find_if(recent.begin(), recent.end(), same) != recent.end();
  }
  void remember(int iteration, const NewtonCheck& check) {
    recent[static_cast<std::size_t>(iteration) % recent.size()] = {check.mismatched,
                                                                   check.largest_mismatch};
  }
  // Fewer contacts out of their mode than after any solve before (remembered).
  bool progress(const NewtonCheck& check) {
    const bool fewer = check.mismatched < fewest_mismatched;
    fewest_mismatched = std::min(fewest_mismatched, check.mismatched);
    return fewer;
  }
  // After contacts were held open the solves ahead see another system: cycles and progress
  // start anew.
  void forget_solves() {
    recent.fill({});
    fewest_mismatched = std::numeric_limits<int>::max();
  }
};

// One solve's Newton direction: the answer d_hat of the system in the present modes, then
// (the Newton step proper) the sliding contacts' friction following the normal force it is
// proportional to (an unsymmetric low-rank term on the kept factor). Held at the iterate's
// normal force instead (Shi's loop; here with KLU, for a non-associated plastic block), it
// converges linearly, as a fixed point: three times the solves of a tumbling square's
// landing. The correction is solved to kGmresTrialTolerance only (an inexact Newton step);
// one that the check finds converged is refined to kGmresTolerance from there and checked
// again, so the accepted answer is as exact as before. Returns the check at d_hat.
NewtonCheck newton_direction(World& world, StepWorkspace& ws, ContactNewton& newton,
                             bool unsymmetric, Eigen::VectorXd& d_hat, bool& friction_follows) {
  friction_follows = false;
  std::optional<Eigen::VectorXd> correction;
  if (!unsymmetric &&
      newton.friction_coupling(world, world.contacts, d_hat, ws.coupling_u,
                               ws.coupling_v, ws.coupling_residual)) {
    reduce_terms(ws.system, ws.coupling_u);
    reduce_terms(ws.system, ws.coupling_v);
    ws.coupling_residual = ws.system.reduce(ws.coupling_residual);
    correction = ws.solver.solve_low_rank_coupled(ws.system, ws.coupling_residual,
                                                  ws.coupling_u, ws.coupling_v,
                                                  CholmodSolver::kGmresTrialTolerance);
    friction_follows = correction.has_value();
  }
  const Eigen::VectorXd d_symmetric = d_hat;
  if (friction_follows) d_hat += ws.system.expand(*correction);
  NewtonCheck check = newton.check(world, world.contacts, d_hat, friction_follows);
  if (friction_follows && check.mismatched == 0) {
    const std::optional<Eigen::VectorXd> refined = ws.solver.solve_low_rank_coupled(
        ws.system, ws.coupling_residual, ws.coupling_u, ws.coupling_v,
        CholmodSolver::kGmresTolerance, &*correction);
    if (refined) {
      d_hat = d_symmetric + ws.system.expand(*refined);
    } else {
      d_hat = d_symmetric;
      friction_follows = false;
    }
    check = newton.check(world, world.contacts, d_hat, friction_follows);
  }
  return check;
}

// What moving the iterate after a solve left out of agreement with the system it will be
// solved from next.
struct NewtonFollowUp {
  int rotation_moved = 0;      // blocks whose T or spin is off the answer (follow_solve)
  int points_moved = 0;        // sliding contacts whose measure point moved
  MaterialFollowUp materials;  // plastic blocks whose Newton iteration has not converged
  int element_modes = 0;       // force elements (bolts) whose mode changed

  bool agrees() const {
    return rotation_moved == 0 && points_moved == 0 && materials.unconverged == 0 &&
           element_modes == 0;
  }
};

// 3'. The converged contact solver (control.contact_solver "newton"; solver/contact_newton.hpp):
//    the modes read off the iterate, a solve with them, a line search towards its answer,
//    until the contacts' responses at the answer agree with the modes it was solved with
//    (and, as in the open-close loop, the secant angles and the plastic blocks' Newton have
//    converged). Bonds break and multipliers grow only on a converged iterate.
LoopResult solve_contact_newton(World& world, StepWorkspace& ws, const StepContext& ctx,
                                LoopTerms& terms, RunStats& stats, StageClock& clock) {
  StageTimes& times = stats.stage_times;
  const RotationTreatment& treatment = treatment_of(world);
  LoopStart start = start_loop(world, ctx, terms);
  const bool plastic = start.plastic, spinning = start.spinning;

  ContactNewton newton(world, world.contacts, ctx);
  NewtonIterate it;
  it.d = Eigen::VectorXd::Zero(world.dof_count);
  it.limit = std::max(world.control.max_open_close, kNewtonIterations) +
             (plastic ? kExtraNewtonIterations : 0);
  newton.start(world, world.contacts, it.d);
  assemble(world, ctx, ws.block_terms);
  clock.lap(times.contact_update);
  LoopResult r;
  for (;;) {
    const bool unsymmetric = unsymmetric_system(terms, plastic);
    const std::optional<Eigen::VectorXd> solved =
        solve_iteration(world, ws, ctx, unsymmetric, r, stats, clock);
    if (!solved) return r;
    Eigen::VectorXd d_hat = *solved;
    bool friction_follows = false;
    NewtonCheck check = newton_direction(world, ws, newton, unsymmetric, d_hat, friction_follows);
    // A cycle (the same mismatch as one of the last kCycleWindow solves) or the limit, with every
    // contact solved closed holding its normal force as solved: only shear modes are left
    // undecided, whose energy the account books as it acted, and contacts solved open that
    // their response would close (they push nothing, so nothing pulls; how far their
    // vertices went in is the overshoot and penetration checks' to judge). The attempt is
    // accepted as solved, as Shi's code accepts one after its loop's cap, and counted with
    // its residual. (A contact in the hopper flipping between a closed solve that ends in
    // tension and an open one that goes 3e3 resolutions in cut 20 steps for open-close.)
    const bool cycling = it.cycling(check);
    it.remember(r.iterations, check);
    const bool at_limit = r.iterations >= it.limit;
    // Not while contacts solved open end inside their edge's block with springs holding more
    // than kAcceptedInsideShare of the run's energy scale: no force did work for that energy,
    // which the next step's springs would give back to the blocks. (A block thrown at a wall
    // and sliding back past the base's corner ended an accepted attempt 3.6 um into the wall
    // at a penalty of 5e12 N/m: 36.6 J/m, 1.4e-3 of its scale, from nothing. Box150's ten
    // accepted attempts hold none.) Such an attempt goes on, and is cut at the limit.
    const bool inside_small = check.open_inside_energy <= kAcceptedInsideShare * world.energy.scale;
    if (check.mismatched > 0 && check.normal_mismatched_closed == 0 && inside_small &&
        (cycling || at_limit)) {
      newton.finish_as_solved(world, world.contacts, d_hat);
      ++stats.newton_accepted_unconverged;
      stats.newton_unconverged_mismatch =
          std::max(stats.newton_unconverged_mismatch, check.largest_mismatch);
      it.d = d_hat;
      break;
    }
    // At the limit with contacts solved closed that pull: they are held open from here on
    // (hold_open_pulling), so the closed set can only shrink through them, and the
    // iteration goes on kHeldOpenIterations more. (A jammed group of eight blocks against
    // the fixed boundary of a 2000-block slope wandered between 3 and 100 mismatched
    // contacts, a dozen of them pulling, until the limit cut the step, at every dt it was
    // tried.) Not at a mere cycle: the damped iterate leaves most cycles that pass through
    // a pulling contact, and holding there sent a 300-polygon hopper into 80 % more
    // overshoot cuts (vertices of held contacts ending inside their edges' blocks).
    if (check.mismatched > 0 && at_limit && it.holds < kHoldOpenRounds) {
      const int held = newton.hold_open_pulling(world, world.contacts, d_hat);
      if (held > 0) {
        ++it.holds;
        stats.newton_held_open += held;
        it.limit += kHeldOpenIterations;
        it.forget_solves();
      }
    }
    // The contacts first, on the present T and material linearisation; once they agree with
    // the solve, the secant angles and the plastic blocks follow it (an outer fixed point:
    // moved with every line-searched iterate, a turning block's T kept a contact at its
    // kink flipping open and closed).
    NewtonFollowUp follow;
    if (check.mismatched > 0) {
      // Whole steps while they make progress (fewer contacts out of their mode than after
      // the last solve: on a pile where many contacts change at once the line search's
      // one length for all of them would find the modes a few at a time), the line search
      // once they do not (a contact cycling between modes).
      const bool progress = it.progress(check);
      double step_length =
          progress ? 1.0 : newton.line_search(world, world.contacts, ws.block_terms, it.d, d_hat);
      // In a cycle the same modes come back whatever the line search says: half its step
      // puts the next iterate between the cycle's states (kCycleDamping).
      if (cycling) step_length *= kCycleDamping;
      if (step_length < 1.0) ++stats.line_searches_shortened;
      it.d += step_length * (d_hat - it.d);
      newton.respond(world, world.contacts, it.d);
    } else {
      it.d = d_hat;
      // The modes at the answer, on the T it was solved with (they agree with the solve),
      // are kept while T and the materials follow it: read again on the new T, a contact
      // at its kink (a corner just landed) would flip open and cost two more solves.
      newton.respond(world, world.contacts, it.d);
      follow.points_moved = newton.follow_measure_points(world, world.contacts, ctx, it.d);
      // T and the spins follow the answer where the treatment iterates them. Blocks in
      // flight may settle block by block first (when no measure point moved and no block is
      // plastic); the contacts then see the new increments and T, and only a contact they
      // change takes the loop on. (The spins, which only the block terms read, follow before
      // the contacts are measured again on the new T.)
      const Followed followed = treatment.follow_solve(
          world, it.d, ctx, terms, start.rotation,
          {spinning, plastic && it.followed_spins_assembled,
           follow.points_moved == 0 && !plastic ? &ws.block_terms : nullptr});
      follow.rotation_moved = followed.moved;
      if (followed.settled_free_blocks) {
        it.followed_spins_assembled = spinning;
        ++stats.local_secant_settles;
        newton.measure(world, world.contacts, ctx);
        check = newton.check(world, world.contacts, it.d, friction_follows);
        if (check.mismatched > 0) newton.respond(world, world.contacts, it.d);
      }
      if (followed.columns_changed) newton.measure(world, world.contacts, ctx);
      if (plastic) {
        follow.materials = follow_materials(world, it.d, terms.material_terms);
        if (follow.materials.failed) {
          r.d = it.d;
          r.unsettled = CutReason::Material;
          r.material_fraction = follow.materials.suggested_fraction;
          r.material_reason = follow.materials.reason;
          return r;
        }
      }
      follow.element_modes = follow_element_modes(world, it.d, ctx, terms);
      if (follow.rotation_moved > 0 || follow.materials.unconverged > 0 ||
          follow.element_modes > 0) {
        assemble(world, ctx, ws.block_terms);
        it.followed_spins_assembled = spinning;
      }
    }
    clock.lap(times.contact_update);
    if (check.mismatched == 0 && follow.agrees()) {
      // Converged: bonds the answer breaks break now, and contacts deeper than allowed grow
      // their multipliers (penetration control, as in the open-close loop); either way the
      // step is solved again.
      int more = newton.break_bonds(world, world.contacts, it.d);
      if (more == 0 && r.augmentations < world.control.max_augmentations &&
          deepest_penetration_share(world.contacts) > 1.0) {
        more = augment_multipliers(world, world.contacts, kAugmentTargetShare, ctx);
        if (more > 0) ++r.augmentations;
      }
      if (more == 0) {
        newton.finish(world, world.contacts, it.d);
        break;
      }
      ++it.limit;
      newton.respond(world, world.contacts, it.d);
    }
    if (r.iterations >= it.limit) {
      newton.finish(world, world.contacts, it.d);
      r.unsettled = CutReason::OpenClose;
      stats.newton_unconverged_mismatch =
          std::max(stats.newton_unconverged_mismatch, check.largest_mismatch);
      break;
    }
  }
  treatment.finish_unknowns(world, it.d);
  r.d = it.d;
  return r;
}

// How deep the vertex of the open contact c ends the step inside the edge's block, by the
// configuration update's own placement (0 if outside, or if it passes the edge's ends).
double overshoot(const World& world, const StepContext& ctx, const Contact& c,
                 const Eigen::VectorXd& d) {
  const Block& bv = world.blocks[static_cast<std::size_t>(c.key.vertex_block)];
  const Block& be = world.blocks[static_cast<std::size_t>(c.key.edge_block)];
  const RotationUpdate treatment = world.control.rotation_update;
  const auto increments = [&d](const Block& b) {
    return b.fixed ? Vec6(Vec6::Zero()) : Vec6(d.segment<6>(b.first_dof));
  };
  // The rotation columns each block was solved with (finite_rotation_polar places by them).
  const Mat2 column_v = solved_rotation_column(&ctx, c.key.vertex_block, increments(bv)[kR0]);
  const Mat2 column_e = solved_rotation_column(&ctx, c.key.edge_block, increments(be)[kR0]);
  const std::size_t n = be.vertices.size();
  const std::size_t k = static_cast<std::size_t>(c.key.edge);
  const Vec2 v = vertex_after(treatment, bv, static_cast<std::size_t>(c.key.vertex),
                              increments(bv), &column_v);
  const EdgeProjection p = project_on_edge(
      v, edge_frame(vertex_after(treatment, be, k, increments(be), &column_e),
                    vertex_after(treatment, be, (k + 1) % n, increments(be), &column_e)));
  if (p.gap >= 0.0 || p.t < 0.0 || p.t > 1.0) return 0.0;
  // Behind the edge's line is not always inside (an acute corner): ask the polygon.
  Polygon after(n);
  for (std::size_t i = 0; i < n; ++i) {
    after[i] = vertex_after(treatment, be, i, increments(be), &column_e);
  }
  return contains_point(after, v) ? -p.gap : 0.0;
}

// A contact deeper than its allowance cuts the step. In a dynamic step, only where a shorter
// step would leave it shallower: when this step deepened it by more than kDeepeningShare of
// its allowance, or when it ends deeper than kPenetrationHardShare of it. (A static step
// starts from rest: no impact, and the multipliers or a shorter step cure the penetration.)
bool penetrates_too_far(const std::vector<Contact>& contacts, bool dynamic) {
  for (const Contact& c : contacts) {
    if (!(c.allowed_penetration > 0.0)) continue;
    const double depth = -c.iterate.new_gap;
    if (depth <= c.allowed_penetration) continue;
    if (!dynamic || depth > kPenetrationHardShare * c.allowed_penetration) return true;
    if (c.gap - c.iterate.new_gap > kDeepeningShare * c.allowed_penetration) return true;
  }
  return false;
}

// 4. The checks on a settled step: too large a motion, a contact deeper than allowed, or an
//    open contact whose vertex ends inside the other block.
//    `moved`: the largest share of its step limit a block moved.
std::optional<CutReason> check_step(const World& world, const StepContext& ctx,
                                    const Eigen::VectorXd& d, double& moved,
                                    double& deepest_overshoot) {
  moved = max_displacement_share(world, d);
  if (moved > 1.0) return CutReason::Displacement;
  if (penetrates_too_far(world.contacts, ctx.dynamic_coefficient > 0.0)) {
    return CutReason::Penetration;
  }
  deepest_overshoot = 0.0;  // as a share of kOvershootShare x the contact's allowance
  for (const Contact& c : world.contacts) {
    if (c.state.mode != ContactMode::Open || !(c.allowed_penetration > 0.0)) continue;
    deepest_overshoot = std::max(deepest_overshoot,
                                 overshoot(world, ctx, c, d) / (kOvershootShare * c.allowed_penetration));
  }
  if (deepest_overshoot > 1.0) return CutReason::Overshoot;
  return std::nullopt;
}

// The one cut rule: the share of dt the redone attempt takes, by reason. The motion is
// roughly proportional to dt, so a displacement cut aims just below the limit; a return map
// that fails suggests its own fraction; contacts that do not settle or penetrate take Shi's
// 0.3; an overshoot, which grows as dt^2, aims just below its limit. Each share is kept
// within Shi's usual range [0.1, 0.9].
double cut_share(CutReason reason, double moved_share, double material_fraction,
                 double overshoot_limit, double overshoot) {
  switch (reason) {
    case CutReason::Displacement: return std::clamp(kCutSafety / moved_share, kCutMin, kCutMax);
    case CutReason::Overshoot:
      return std::clamp(kCutSafety * std::sqrt(overshoot_limit / overshoot), kCutMin, kCutMax);
    case CutReason::Material: return std::clamp(material_fraction, kCutMin, kCutMax);
    case CutReason::OpenClose:
    case CutReason::Penetration: return kContactCut;
  }
  return kContactCut;
}

void count_cut(CutReason reason, RunStats& stats) {
  ++stats.cut_steps;
  switch (reason) {
    case CutReason::Displacement: ++stats.cuts_for_displacement; break;
    case CutReason::OpenClose: ++stats.cuts_for_open_close; break;
    case CutReason::Penetration: ++stats.cuts_for_penetration; break;
    case CutReason::Material: ++stats.cuts_for_material; break;
    case CutReason::Overshoot: ++stats.cuts_for_overshoot; break;
  }
}

// 5-6. Commit: the energy account's terms (on the step's own T and contacts), the
//    configuration update by the chosen rotation treatment, strains, stresses, velocities,
//    time; then the account's balance.
void commit_step(World& world, const Eigen::VectorXd& d,
                 const StepContext& ctx, int iterations, RunStats& stats, StageClock& clock,
                 StepEnergy& energy_terms) {
  energy_terms = step_energy(world, world.contacts, d, ctx);
  commit_elements(world, d, ctx);
  update_configuration(world, d, &ctx);
  update_stresses(world);
  update_velocities(world, d, ctx);
  clock.lap(stats.stage_times.update);
  world.time += ctx.dt;
  ++world.step;
  commit_step_energy(world, energy_terms, world.contacts, ctx.penalty);
  record_spring_energies(world.contacts, ctx.penalty);
  record_slips(world.contacts);
  count_step(world, iterations, stats);
}

// The step size that remembers (World::step_size), at the acceptance of a step of length dt
// whose first attempt was first_dt (the schedule's, `scheduled_dt`, or the remembered step if
// shorter). A step that was cut leaves the step that worked for the next one to start from; a
// step that worked at the remembered size lets the next try kStepGrowth times longer. Neither
// goes beyond what the accepted step's motion says fits: `moved`, the share of its limit the
// block that moved most used, is aimed at kCutSafety, the cut rule's own aim, whether the
// motion follows dt (a moving block) or dt^2 (a block starting from rest, as in every static
// step); the smaller factor of the two is taken. A memory that reaches the longest step of the
// schedule is dropped: the schedule rules again. A step the schedule made shorter than the
// memory (end_time, a stage's end, the shorter entry of a cyclic list) teaches nothing and
// leaves the memory as it was. Also counts the step's length in `stats`.
void remember_step(World& world, double scheduled_dt, double first_dt, double dt, bool was_cut,
                   double moved, RunStats& stats) {
  const std::vector<double>& list = world.control.time_steps;
  const double listed = list[static_cast<std::size_t>(world.step) % list.size()];
  const bool landing = !was_cut && dt == scheduled_dt && scheduled_dt < listed;  // on end_time
  if (!landing) {
    stats.smallest_time_step =
        stats.smallest_time_step > 0.0 ? std::min(stats.smallest_time_step, dt) : dt;
    stats.largest_time_step = std::max(stats.largest_time_step, dt);
  }
  if (dt < scheduled_dt) ++stats.steps_below_schedule;

  StepSizeMemory& memory = world.step_size;
  const double room = moved > 0.0 ? kCutSafety / moved : kStepGrowth;
  const double fits = std::min(room, std::sqrt(room));
  double next = 0.0;
  if (was_cut) {
    next = dt * std::min(1.0, fits);
  } else if (memory.next > 0.0 && first_dt == memory.next) {
    next = dt * std::min(kStepGrowth, fits);
  } else {
    return;  // the schedule's own step, or one it made shorter than the memory
  }
  const double longest = *std::max_element(list.begin(), list.end());
  memory.next = next < longest ? next : 0.0;
}

// The bonds the accepted step broke (bonded as the step entered, not at its end; the
// contacts keep their order through a step), counted and placed in stats.
void count_broken_bonds(const World& world, const std::vector<Contact>& at_start, RunStats& stats) {
  for (std::size_t i = 0; i < at_start.size() && i < world.contacts.size(); ++i) {
    const Contact& c = world.contacts[i];
    if (!at_start[i].state.bonded || c.state.bonded) continue;
    ++stats.bonds_broken;
    if (stats.broken_bonds.size() >= RunStats::kBrokenBondsKept) continue;
    const Block& b = world.blocks[static_cast<std::size_t>(c.key.vertex_block)];
    stats.broken_bonds.push_back({world.step, world.time, c.key.vertex_block, c.key.edge_block,
                                  b.vertices[static_cast<std::size_t>(c.key.vertex)]});
  }
}

}  // namespace

StepOutcome advance_step(World& world, StepWorkspace& ws, RunStats& stats) {
  StageClock clock;
  ws.solver.set_reuse(world.control.reuse_factor);
  // 1. Choose dt: the schedule's, or the step size remembered after a cut if that is shorter
  //    (World::step_size; remember_step updates it when the step is accepted).
  const double scheduled_dt = scheduled_time_step(world);
  const double first_dt = time_step_to_try(world);
  double dt = first_dt;
  // 2. Contact detection on the configuration at the step's start, as far as each block may
  //    reach in the first attempt (a cut attempt reaches less); contacts keep the state
  //    they had last step. A redone attempt starts again from these. (The pair list the
  //    workspace carries is only a shortcut: the contacts are those of a full detection.)
  set_reaches(world, first_dt);
  detect_contacts(world, world.contacts, ws.detection);
  stats.candidate_pairs_max =
      std::max(stats.candidate_pairs_max, static_cast<long>(ws.detection.close.size()));
  const std::vector<Contact> contacts_at_start = world.contacts;
  // 2b. Joint water pressure on the faces those contacts share, constant over the step
  //     (present_water_forces: weighing what the stage's gravity makes it weigh).
  const std::vector<BlockForce> water_forces = present_water_forces(world);
  clock.lap(stats.stage_times.detect);
  int penetration_cuts = 0;
  bool was_cut = false;
  // What made the last attempt fail when a shorter step may not cure it: a return map that
  // failed ("the material of block ..."), or a block turned inside out; empty otherwise.
  std::string block_failure;

  for (;;) {
    if (dt < kSmallestStepShare * scheduled_dt) {
      if (!block_failure.empty()) {
        // Shorter steps did not cure it: say which block and why, not "the contacts do not
        // settle" (a Mohr-Coulomb block without a tension cut-off hit by an impact that puts
        // it in tension beyond its apex cut 209 steps before this).
        return {false, describe_failure(world, block_failure + ", at every step length down "
                                                               "to 1e-9 of the scheduled one")};
      }
      return {false, describe_failure(world, "time step cut below 1e-9 of the scheduled one; "
                                             "the contacts or the motion do not settle")};
    }
    // The attempt's settings, fixed, and the terms its contact loop iterates, apart.
    LoopTerms terms;
    const StepContext ctx = make_step_context(world, dt, water_forces, terms);
    world.contacts = contacts_at_start;  // states as they entered the step, no changes counted
    // 3. The open-close loop.
    const LoopResult loop = world.control.contact_solver == ContactSolver::Newton
                                ? solve_contact_newton(world, ws, ctx, terms, stats, clock)
                                : solve_open_close(world, ws, ctx, terms, stats, clock);
    stats.augmentations += loop.augmentations;
    if (!loop.solved) {
      return {false, describe_failure(world, "the global system could not be solved "
                                             "(not positive definite or not finite)" +
                                                 crushed_block_note(world))};
    }
    // 4. Checks: an unsettled loop, too large a motion or too deep a penetration cut dt and
    //    redo the attempt. The penalty is never changed: raising it while contacts are loaded
    //    put energy into them, and a run must not change its model silently. A penetration
    //    that cutting does not cure (a static load the penalty cannot carry within
    //    allowed_penetration) ends the run with a message that says so.
    double moved = 0.0, deepest_overshoot = 0.0;
    const std::optional<CutReason> cut =
        loop.unsettled ? loop.unsettled : check_step(world, ctx, loop.d, moved, deepest_overshoot);
    if (cut) {
      if (*cut == CutReason::Penetration &&
          (++penetration_cuts > kPenetrationCuts || dt <= kPenetrationFloor * scheduled_dt)) {
        std::ostringstream what;
        const auto deepest = std::max_element(
            world.contacts.begin(), world.contacts.end(), [](const Contact& a, const Contact& b) {
              return -a.iterate.new_gap * b.allowed_penetration < -b.iterate.new_gap * a.allowed_penetration;
            });
        what << "contacts penetrate " << -deepest->iterate.new_gap
             << " m, more than allowed_penetration " << deepest->allowed_penetration << " m, even at "
             << dt / scheduled_dt << " of the scheduled time step: the load needs a stiffer "
             << "contact; raise control.penalty (now " << world.penalty
             << " N/m) or control.allowed_penetration";
        return {false, describe_failure(world, what.str())};
      }
      block_failure = *cut == CutReason::Material && !loop.material_reason.empty()
                          ? "the material of " + loop.material_reason
                          : std::string();
      count_cut(*cut, stats);
      was_cut = true;
      dt *= cut_share(*cut, moved, loop.material_fraction, 1.0, deepest_overshoot);
      continue;
    }
    // 4b. A block the step would turn inside out (its area through zero: a block far too soft
    //     for its load, crushed over a few steps) is a motion too large for the step: cut,
    //     and when no step length keeps it whole, stop naming it (committed, its polar
    //     decomposition wrote nan into the state).
    if (const std::optional<std::size_t> inverted = first_inverted_block(world, loop.d, ctx)) {
      const Block& b = world.blocks[*inverted];
      std::ostringstream what;
      what << "block " << *inverted << " is turned inside out: its area (" << b.moments.area
           << " m^2 at the step's start, " << b.initial_area << " at the run's) falls through "
           << "zero; its material is far too soft for its load";
      block_failure = what.str();
      count_cut(CutReason::Displacement, stats);
      was_cut = true;
      dt *= kCutMin;
      continue;
    }
    remember_step(world, scheduled_dt, first_dt, dt, was_cut, moved, stats);
    // 5-6. Commit the step.
    StepEnergy energy_terms;
    commit_step(world, loop.d, ctx, loop.iterations, stats, clock, energy_terms);
    count_broken_bonds(world, contacts_at_start, stats);
    // 7. The energy guard: a step that leaves the run with more energy than loads put in
    //    (beyond the tolerance) ends it; the step is kept, so the output shows it.
    std::string gained = energy_guard_message(world, energy_terms, world.control.energy_tolerance);
    if (!gained.empty()) return {false, std::move(gained)};
    //    With control.energy_losses "stop", a loss no term books ends it too.
    if (world.control.stop_on_energy_loss) {
      std::string lost = energy_loss_message(world, world.control.energy_tolerance);
      if (!lost.empty()) return {false, std::move(lost)};
    }
    return {};
  }
}

}  // namespace dda
