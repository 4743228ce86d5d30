// One DDA time step (advance_step, step.cpp, read top-down): choose dt, detect_contacts,
// solve_open_close, check_step (cut and redo), commit_step, the energy guard.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contact/contact.hpp"

#include "solver/block_system.hpp"
#include "solver/contact_detection.hpp"
#include "solver/factor_springs.hpp"
#include "solver/linear_solver.hpp"
#include "solver/run_stats.hpp"
#include "solver/world.hpp"

namespace dda {

// What the step loop keeps between steps: buffers, the factorisation's analysis and the
// broad phase's pair list (the contacts are the world's).
struct StepWorkspace {
  DetectionCache detection;       // checked against the world on every detection
  BlockSystem block_terms;        // the blocks' own terms, assembled once per attempt
  BlockSystem system;             // block terms plus the contacts of one open-close iteration
  CholmodSolver solver;
  FactorSprings factor_springs;              // the contact springs in the solver's factor
  std::vector<RankOneTerm> springs_added;    // contact springs to put into the factor,
  std::vector<RankOneTerm> springs_removed;  // and those to take out (scratch)
  // The converged contact solver's friction coupling (ContactNewton::friction_coupling).
  std::vector<RankOneTerm> coupling_u, coupling_v;
  Eigen::VectorXd coupling_residual;
};

// Why an attempt of a step is thrown away and redone with a shorter dt (one cut rule,
// step.cpp: cut_share).
enum class CutReason {
  Displacement,  // a vertex moved more than its block's step limit (Block::step_limit)
  OpenClose,     // the open-close loop did not settle in max_open_close iterations
  Penetration,   // a contact ended deeper than allowed_penetration
  Material,      // a plastic block's return map failed
  Overshoot,     // an open contact's vertex ends the step inside the other block
};

struct StepOutcome {
  bool ok = true;
  std::string message;  // why the step failed (divergence), empty when ok
};

// The time step the schedule asks for at the world's current step: the list is used
// cyclically, and the last step is shortened to land on end_time.
double scheduled_time_step(const World& world);

// The step the next step tries first: the schedule's, or the step size remembered after a cut
// (World::step_size) when that is shorter. A cut shortens it further; a step that worked at
// the remembered size lets the next try up to 1.2 times longer, back to the schedule.
double time_step_to_try(const World& world);

// True when the world has done its steps or reached its end time.
bool is_finished(const World& world);

// Advances the world by one step; counts solves and cut attempts in `stats`.
StepOutcome advance_step(World& world, StepWorkspace& ws, RunStats& stats);

}  // namespace dda
