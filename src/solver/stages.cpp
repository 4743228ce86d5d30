#include "solver/stages.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "contact/bonding.hpp"
#include "solver/excavation.hpp"
#include "solver/schedule.hpp"
#include "solver/step.hpp"
#include "solver/world.hpp"

namespace dda {
namespace {

double stage_start(const StagePlan& plan, int stage) {
  return stage == 0 ? 0.0 : plan.end_times[static_cast<std::size_t>(stage - 1)];
}

// Sets world.gravity to `g`. The blocks' potential energy, -m g . xc, then changes with no
// motion: that change is work done on the scene from outside (by whatever changes gravity),
// booked as load work, so the energy account stays balanced under a ramp (energy.hpp).
void change_gravity(World& world, const Vec2& g) {
  if (g == world.gravity) return;
  const Vec2 change = g - world.gravity;
  for (const Block& b : world.blocks) {
    if (b.fixed) continue;
    world.energy.load_work -= block_mass(world, b) * change.dot(b.moments.centroid);
  }
  world.gravity = g;
}

// The stage's settings into the world fields the step reads, and its excavation.
void enter_stage(World& world, int stage, std::vector<Contact>& contacts) {
  StagePlan& plan = world.stages;
  const StageSpec& s = plan.stages[static_cast<std::size_t>(stage)];
  assert(s.duration > 0.0 && !s.time_steps.empty());  // resolved by the reader
  plan.current = stage;
  plan.start_steps.push_back(world.step);
  plan.bonds_formed.push_back(0);
  world.control.time_steps = s.time_steps;
  world.control.dynamic_coefficient = s.dynamic_coefficient;
  world.control.steps.reset();
  world.control.end_time = plan.end_times[static_cast<std::size_t>(stage)];
  world.step_size = StepSizeMemory{};  // the stage starts from its own schedule
  world.joint_laws = plan.joint_laws;
  for (const StageJoint& o : s.joint_materials) {
    world.joint_laws[static_cast<std::size_t>(o.joint)] = joint_law_of(o.material);
  }
  change_gravity(world, stage_gravity_factor(plan, stage, stage_start(plan, stage)) * plan.gravity);
  excavate_blocks(world, contacts, s.excavate);
}

}  // namespace

JointLaw joint_law_of(const JointMaterial& j) {
  JointLaw law{std::tan(j.friction_angle * M_PI / 180.0), j.cohesion, j.tensile_strength, j.law};
  if (j.residual_slip > 0.0) {
    law.residual_tan_phi = std::tan(j.residual_friction_angle * M_PI / 180.0);
    law.residual_cohesion = j.residual_cohesion;
    law.residual_slip = j.residual_slip;
  }
  law.jrc = j.jrc;
  law.jcs = j.jcs;
  return law;
}

void start_stages(World& world, const Scene& scene) {
  if (scene.stages.empty()) return;
  // After the energy account has started (make_world): its start and its scale see the
  // scene's full gravity, and a first stage that scales it books the change as load work.
  StagePlan& plan = world.stages;
  plan.stages = scene.stages;
  double end = 0.0;  // summed as the reader sums them: the last is scene.control.end_time
  for (const StageSpec& s : scene.stages) plan.end_times.push_back(end += s.duration);
  plan.gravity = world.gravity;
  plan.control = world.control;
  plan.joint_laws = world.joint_laws;
  enter_stage(world, 0, world.contacts);
}

bool enter_next_stage(World& world, std::vector<Contact>& contacts) {
  StagePlan& plan = world.stages;
  if (plan.stages.empty() || !is_finished(world)) return false;
  const int next = plan.current + 1;
  if (static_cast<std::size_t>(next) >= plan.stages.size()) return false;
  enter_stage(world, next, contacts);
  if (plan.stages[static_cast<std::size_t>(next)].bond_closed_contacts) {
    plan.bonds_formed.back() = bond_closed_contacts(contacts, world.joint_laws);
  }
  return true;
}

void set_stage_gravity(World& world) {
  const StagePlan& plan = world.stages;
  if (plan.stages.empty()) return;
  const double step_end = world.time + time_step_to_try(world);
  change_gravity(world, stage_gravity_factor(plan, plan.current, step_end) * plan.gravity);
}

double stage_gravity_factor(const StagePlan& plan, int stage, double t) {
  const StageSpec& s = plan.stages[static_cast<std::size_t>(stage)];
  if (!s.gravity_ramp) return s.gravity_to;
  const double start = stage_start(plan, stage);
  const double end = plan.end_times[static_cast<std::size_t>(stage)];
  // The stage's last step lands on its end up to round-off, as is_finished takes it.
  if (reached_time(t, end, s.time_steps)) return s.gravity_to;
  const double share = std::clamp((t - start) / s.duration, 0.0, 1.0);
  return s.gravity_from + (s.gravity_to - s.gravity_from) * share;
}

}  // namespace dda
