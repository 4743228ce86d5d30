#include "solver/material_coupling.hpp"

#include <algorithm>

#include "kinematics/frames.hpp"
#include "solver/configuration_update.hpp"
#include "materials/material.hpp"
#include "solver/rotation/treatment.hpp"

namespace dda {
namespace {

struct Evaluation {
  MaterialResult result;
  Vec3 stress = Vec3::Zero();   // global
  Mat3 tangent = Mat3::Zero();  // global, d stress / d global strain increment
};

Evaluation evaluate(const World& world, const Block& b, const Vec6& db) {
  const bool in_frame = treatment_of(world).keeps_frame();
  Evaluation e;
  e.result = integrate(material_of(world, b), b.material_state,
                       material_strain_after(world, b, db), initial_stress4(world, b));
  const Vec3 local_stress = in_plane(e.result.stress);
  if (!in_frame) {
    e.stress = local_stress;
    e.tangent = e.result.tangent;
    return e;
  }
  // The step's equations see the stress in the frame the block has at the step's start,
  // as they see an elastic block's (Shi's step does not turn the stress it starts with):
  // global stress = S(r) s_local, increment into the frame by E(r), r the start angle. For
  // an isotropic elastic response S D E = D, so a plastic block that does not yield solves
  // exactly the elastic block's equations and its Newton iteration stops after one solve.
  // The update then turns the committed stress by the end angle, for both.
  const double r = b.rotation;
  e.stress = stress_from_turned_frame(local_stress, r);
  Mat3 into = Mat3::Zero(), out = Mat3::Zero();
  for (int k = 0; k < 3; ++k) {
    into.col(k) = strain_in_turned_frame(Vec3::Unit(k), r);
    out.col(k) = stress_from_turned_frame(Vec3::Unit(k), r);
  }
  e.tangent = out * e.result.tangent * into;
  return e;
}

// An associated return's tangent is symmetric up to round-off; a non-associated one's is not,
// and then the step is solved with KLU instead of CHOLMOD (solver/step.cpp). Within this
// share of its norm the tangent is taken as symmetric and symmetrised exactly, so that
// CHOLMOD, which reads one triangle, sees the same matrix.
constexpr double kSymmetryTolerance = 1e-12;

}  // namespace

bool any_unsymmetric(const std::vector<MaterialLinearization>& terms) {
  return std::any_of(terms.begin(), terms.end(),
                     [](const MaterialLinearization& l) { return !l.symmetric; });
}

bool has_plastic_blocks(const World& world) {
  return std::any_of(world.blocks.begin(), world.blocks.end(),
                     [](const Block& b) { return b.plastic; });
}

std::vector<MaterialLinearization> start_linearization(const World& world) {
  std::vector<MaterialLinearization> terms(world.blocks.size());
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (!b.plastic) continue;
    terms[i].stress = b.stress;
    // Isotropic D is the same in every frame.
    terms[i].tangent = elastic_of(world, b);
  }
  return terms;
}

Vec3 material_strain_after(const World& world, const Block& b, const Vec6& db) {
  const Vec3 increment = db.segment<3>(kEx);
  if (!treatment_of(world).keeps_frame()) return b.strain + increment;
  // The start angle, as in evaluate(); the update adds the same increment at the mid-step
  // angle, a difference of r0/2 of the increment's turn, second order in the step.
  // finite_rotation_polar's update commits the Hencky strain of the map the step applied
  // instead, ln U', whose derivative with respect to the global increment is this turn up
  // to O(|H|^2) (docs/large-strain.md): the step is linear in the block's strain, as for
  // finite_rotation, and an elastic block's equations are those of a plastic block that
  // does not yield; what the linearisation leaves, O(|H|^2 de + de^2), is committed with the
  // strain and so starts the next step (never accumulated: the strain is total).
  return b.local_strain + strain_in_turned_frame(increment, b.rotation);
}

MaterialFollowUp follow_materials(const World& world, const Eigen::VectorXd& d,
                                  std::vector<MaterialLinearization>& terms) {
  MaterialFollowUp follow;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (!b.plastic) continue;
    const Vec6 db = d.segment<6>(b.first_dof);
    const Evaluation e = evaluate(world, b, db);
    if (!e.result.status.converged) {
      follow.failed = true;
      follow.suggested_fraction =
          std::min(follow.suggested_fraction, e.result.status.suggested_fraction);
      follow.reason = "block " + std::to_string(i) + ": " + e.result.status.reason;
      continue;
    }
    MaterialLinearization& l = terms[i];
    const Vec3 increment = db.segment<3>(kEx);
    const Vec3 predicted = l.stress + l.tangent * (increment - l.strain_increment);
    const double scale = std::max(e.stress.norm(), 1e-12 * material_of(world, b).young);
    if ((e.stress - predicted).norm() > kNewtonRelativeTolerance * scale) ++follow.unconverged;
    l.strain_increment = increment;
    l.stress = e.stress;
    const Mat3 skew = 0.5 * (e.tangent - e.tangent.transpose());
    l.symmetric = skew.norm() <= kSymmetryTolerance * e.tangent.norm();
    l.tangent = l.symmetric ? Mat3(e.tangent - skew) : e.tangent;
  }
  return follow;
}

}  // namespace dda
