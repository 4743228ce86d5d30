// Scene stages (docs/scene-format.md, "stages"): settings that change at given times, e.g.
// a static consolidation with gravity ramped up, then a dynamic run. The run loop
// (solver/run.cpp) moves the world from one stage to the next and sets the stage's gravity
// before each step; the step reads them where it always has: world.gravity,
// world.control (time step, dynamic coefficient, end time) and world.joint_laws.
#pragma once

#include <vector>

#include "contact/contact.hpp"
#include "contact/joint_law.hpp"
#include "kinematics/types.hpp"
#include "solver/scene.hpp"

namespace dda {

struct World;

// The stages of a world and what they change from (World::stages). Without stages it is
// empty and nothing here touches the world.
struct StagePlan {
  std::vector<StageSpec> stages;
  std::vector<double> end_times;  // s: running sums of the durations; the last is the run's end
  // What the stages scale or replace: the scene's gravity, control and joint laws.
  Vec2 gravity = Vec2::Zero();
  ControlSettings control;
  std::vector<JointLaw> joint_laws;
  int current = -1;  // the stage running (from 0); -1 without stages
  // Per stage entered so far: the completed steps when it began, and the bonds formed at
  // its start (bond_closed_contacts; 0 when it forms none).
  std::vector<int> start_steps;
  std::vector<int> bonds_formed;
};

// The joint law of a joint material: tan of the friction angle, cohesion, tensile strength.
JointLaw joint_law_of(const JointMaterial& j);

// Sets up the world's stages from the scene and enters the first (make_world calls it once
// the world's own gravity, control and joint laws are the scene's). No stages: nothing.
void start_stages(World& world, const Scene& scene);

// When the world has finished its current stage (is_finished) and another follows: enters it
// (its gravity at its start, time steps, dynamic coefficient, end time and joint laws), forms
// its bonds on `contacts` when it asks for them, and returns true. Otherwise returns false and
// changes nothing.
bool enter_next_stage(World& world, std::vector<Contact>& contacts);

// Sets world.gravity for the coming step: the scene's gravity times the stage's factor at the
// end of the step's first attempt (time_step_to_try: the schedule's step, or the remembered
// one after a cut; a ramp reaches its last factor on the stage's last step, which is
// shortened to land on the stage's end). No stages: nothing.
void set_stage_gravity(World& world);

// The stage's gravity factor at time t (s), linear over the stage for a ramp; exactly
// gravity_to from the stage's end on.
double stage_gravity_factor(const StagePlan& plan, int stage, double t);

}  // namespace dda
