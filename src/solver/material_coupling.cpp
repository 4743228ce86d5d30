#include "solver/material_coupling.hpp"

#include <algorithm>

#include "kinematics/frames.hpp"

namespace dda {
namespace {

// Angles of the block frame over the step, written exactly as configuration_update.cpp
// writes them, so that the converged Newton stress and the stress of the update agree to
// the last bit: the strain increment enters the frame at the mid-step angle, the stress
// leaves it at the end angle.
struct StepAngles {
  double mid = 0.0;
  double end = 0.0;
};

StepAngles angles_of(const Block& b, const Vec6& db) {
  const double end = b.rotation + db[kR0];
  return {end - 0.5 * db[kR0], end};
}

struct Evaluation {
  MaterialResult result;
  Vec3 stress = Vec3::Zero();   // global
  Mat3 tangent = Mat3::Zero();  // global, d stress / d global strain increment
};

Evaluation evaluate(const World& world, const Block& b, const Vec6& db) {
  const bool in_frame = keeps_block_frame(world.control.rotation_update);
  Evaluation e;
  e.result = integrate(b.material_parameters, b.material_state,
                       material_strain_after(world, b, db), b.initial_stress_4);
  const Vec3 local_stress = in_plane(e.result.stress);
  if (!in_frame) {
    e.stress = local_stress;
    e.tangent = e.result.tangent;
    return e;
  }
  // d(global stress)/d(global increment) = S(end) D_t E(mid), with E the strain turn into
  // the frame and S the stress turn out of it (both linear; their matrices column by
  // column). The angles' own dependence on r0 is left out of the tangent.
  const StepAngles a = angles_of(b, db);
  e.stress = stress_from_turned_frame(local_stress, a.end);
  Mat3 into = Mat3::Zero(), out = Mat3::Zero();
  for (int k = 0; k < 3; ++k) {
    into.col(k) = strain_in_turned_frame(Vec3::Unit(k), a.mid);
    out.col(k) = stress_from_turned_frame(Vec3::Unit(k), a.end);
  }
  e.tangent = out * e.result.tangent * into;
  return e;
}

// The step's equations are symmetric (CHOLMOD LDL'): a non-associated return's tangent is
// not, and enters by its symmetric part, which makes the Newton iteration converge linearly
// instead of quadratically for non-associated flow (associated flow keeps it exact).
Mat3 symmetric_part(const Mat3& m) { return 0.5 * (m + m.transpose()); }

}  // namespace

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
    terms[i].tangent = b.elastic;
  }
  return terms;
}

Vec3 material_strain_after(const World& world, const Block& b, const Vec6& db) {
  const Vec3 increment = db.segment<3>(kEx);
  if (!keeps_block_frame(world.control.rotation_update)) return b.strain + increment;
  return b.local_strain + strain_in_turned_frame(increment, angles_of(b, db).mid);
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
    const double scale = std::max(e.stress.norm(), 1e-12 * b.material_parameters.young);
    if ((e.stress - predicted).norm() > kNewtonRelativeTolerance * scale) ++follow.unconverged;
    l.strain_increment = increment;
    l.stress = e.stress;
    l.tangent = symmetric_part(e.tangent);
  }
  return follow;
}

}  // namespace dda
