// Plastic blocks inside the DDA step.
//
// A plastic block's stress is the material library's answer for the total strain its
// treatment accumulates (in the block frame for the local-frame treatments, global for the
// others), never an accumulated stress. The step's equilibrium is then nonlinear in the
// block's strain increment; it is solved by Newton with the consistent tangent, nested in
// the open-close loop: every loop iteration assembles the blocks' material linearised at the
// last solution (MaterialLinearization), solves, lets the contacts choose their modes, and
// re-evaluates the materials at the new increments. The loop ends when no contact changes
// and every plastic block's stress equals its linear prediction (Newton converged).
// Elastic blocks are never linearised here: a scene without plastic blocks pays nothing.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

bool has_plastic_blocks(const World& world);

// True when some plastic block's tangent is unsymmetric (non-associated flow while
// yielding): the step's system must then be solved by LU (KLU), not LDL'.
bool any_unsymmetric(const std::vector<MaterialLinearization>& terms);

// The Newton start of a step: the elastic tangent at zero increment, from the stress at the
// step's start (an elastic predictor).
std::vector<MaterialLinearization> start_linearization(const World& world);

// The strain the material of block b sees at the end of the step with increments db, as the
// step's Newton iteration takes it (increment turned into the frame at the start angle).
Vec3 material_strain_after(const World& world, const Block& b, const Vec6& db);

struct MaterialFollowUp {
  int unconverged = 0;   // plastic blocks whose stress left the linear prediction
  bool failed = false;   // a return map failed: cut the step
  double suggested_fraction = 1.0;  // of dt, from the material's own suggestion
  std::string reason;
};

// After a solve: evaluates every plastic block's material at the solved increments, counts
// those not yet in equilibrium with their linearisation, and re-linearises them there.
MaterialFollowUp follow_materials(const World& world, const Eigen::VectorXd& d,
                                  std::vector<MaterialLinearization>& terms);

// A block's stress ends a Newton iteration converged when the material's stress at the
// solved increment is within this share of the stress scale of the linear prediction:
// the out-of-balance force is then 1e-9 of the block's own stress forces, far below the
// penalty springs' round-off. The scale has a floor of young x 1e-12 (the stress of a strain
// at round-off) for blocks at rest.
constexpr double kNewtonRelativeTolerance = 1e-9;

}  // namespace dda
