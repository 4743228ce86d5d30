// What a run counts and times (RunStats): filled by the step (solver/step.hpp) and reported
// by the run loop (solver/run.hpp) and the output. Plain data, so that the step need not
// know the run loop.
#pragma once

#include <string>
#include <vector>

#include "kinematics/types.hpp"

namespace dda {

// Wall time spent in each stage of the step (seconds, summed over the run), to show where
// the time goes (bench/, README "Speed").
struct StageTimes {
  double detect = 0;          // broad and narrow phase, state carried over
  double assemble = 0;        // block terms and, per open-close iteration, contact terms
  double solve = 0;           // linear solves: CHOLMOD (kept factor, its updates, CG) or KLU
  double contact_update = 0;  // each contact's next mode after a solve
  double update = 0;          // configuration, stresses, velocities
};

// A bond that broke: at which step and time, between which blocks, and where (the vertex
// of the contact, at the step's end).
struct BrokenBond {
  int step = 0;
  double time = 0.0;
  int vertex_block = -1, edge_block = -1;
  Vec2 at = Vec2::Zero();
};

struct RunStats {
  int steps = 0;           // completed steps
  int cut_steps = 0;       // attempts thrown away and redone with a shorter dt, for:
  int cuts_for_displacement = 0;  //   a vertex moved more than its block's step limit
  int cuts_for_open_close = 0;    //   open-close loop not settled in max_open_close
  int cuts_for_penetration = 0;   //   a contact deeper than allowed_penetration
  int cuts_for_material = 0;      //   a plastic block's return map failed
  int cuts_for_overshoot = 0;     //   an open contact's vertex ended inside the other block
  // The accepted steps' lengths (s), the last step shortened only to land on end_time (or a
  // stage's end) left out: the shortest and the longest (0 before any), and how many steps
  // were shorter than the schedule asked (cut, or started from the step size remembered
  // after a cut: solver/step.cpp, advance_step).
  double smallest_time_step = 0.0;
  double largest_time_step = 0.0;
  int steps_below_schedule = 0;
  long iterations = 0;     // linear solves (assemble + solve passes) in all
  double wall_time_s = 0;  // whole run, seconds
  long open_close_total = 0;  // open-close iterations of accepted steps, summed
  int open_close_max = 0;     // the most any accepted step needed
  long contacts_total = 0;    // closed contacts at the end of each step, summed
  int contacts_max = 0;
  int contacts_final = 0;     // closed contacts at the end of the run
  // The most block pairs the broad phase handed to the narrow phase in a step (pairs within
  // their search distance, fixed pairs included): what the contact search costs.
  long candidate_pairs_max = 0;
  // The observer stopped the run before its end: dda run's does so on SIGINT or SIGTERM
  // (summary.json's "interrupted"), a fos trial's once its verdict is known. The state
  // reached is complete, only shorter than asked.
  bool interrupted = false;
  double deepest_penetration = 0.0;   // m, deepest contact penetration after any accepted step
  double largest_normal_force = 0.0;  // N/m, largest contact normal force after any accepted step
  // Augmented-Lagrangian rounds (solver/step.cpp, control.max_augmentations): solves spent pushing
  // contacts deeper than allowed_penetration back out at the fixed penalty.
  long augmentations = 0;
  // The converged contact solver (control.contact_solver "newton"): solves whose answer was
  // taken only in part by the line search, and the largest mismatch (as a share of the
  // contact resolution) of an attempt cut because it did not converge (0: none was).
  long line_searches_shortened = 0;
  double newton_unconverged_mismatch = 0.0;
  // Attempts it accepted unconverged (a cycle or its limit with only shear modes left,
  // solver/step.cpp), as Shi's code accepts a step after its loop's cap.
  long newton_accepted_unconverged = 0;
  // Contacts it held open for the rest of an attempt that was stuck with contacts solved
  // closed pulling (ContactNewton::hold_open_pulling).
  long newton_held_open = 0;
  // Bonds broken in accepted steps (a contact bonded at a step's start and not at its end),
  // and where: the first kBrokenBondsKept of them, in order.
  long bonds_broken = 0;
  std::vector<BrokenBond> broken_bonds;
  static constexpr std::size_t kBrokenBondsKept = 1000;
  // finite_rotation: converged solves whose off secant angles were all of blocks touching
  // nothing, settled block by block instead of by one more solve (settle_free_secants).
  long local_secant_settles = 0;
  StageTimes stage_times;
  bool diverged = false;
  std::string message;     // why the run stopped early, empty otherwise
};

}  // namespace dda
