// An alternative to the hand-written Newton of the step loop:
// KINSOL's Newton with a sparse direct linear solve (SUNDIALS' KLU) on one step's
// equilibrium with the contact modes held fixed. Used to measure the two against each other
// (bench/bench_newton.cpp) and to check that they find the same increments (tests).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "contact/contact.hpp"
#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

struct KinsolStepResult {
  bool ok = false;
  Eigen::VectorXd d;         // the step's increments
  long iterations = 0;       // Newton iterations
  long residual_evals = 0;   // residual (assembly + material) evaluations
  std::string message;       // KINSOL's flag when !ok
};

// Solves R(d) = K(d) d - f(d) = 0 for the step of `ctx` (dt, penalty; its material terms
// are rebuilt at every residual) with `contacts` in their present modes. The Jacobian is
// the assembled matrix with the plastic blocks' consistent tangents (unsymmetric allowed).
// Stops when the max-norm of R is below `tolerance` (N).
KinsolStepResult solve_step_with_kinsol(const World& world, const std::vector<Contact>& contacts,
                                        const StepContext& ctx, double tolerance);

}  // namespace dda
