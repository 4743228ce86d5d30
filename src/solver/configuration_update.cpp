#include "solver/configuration_update.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "kinematics/block_matrices.hpp"
#include "kinematics/frames.hpp"
#include "kinematics/point_maps.hpp"
#include "materials/material.hpp"
#include "solver/rotation/carried_points.hpp"
#include "solver/rotation/rotation_columns.hpp"
#include "solver/rotation/treatment.hpp"

namespace dda {
namespace {

void remember_rotation_increments(World& world, const Eigen::VectorXd& d) {
  for (Block& b : world.blocks) {
    if (!b.fixed) b.last_rotation_increment = d[b.first_dof + kR0];
  }
}

}  // namespace

bool spatial_increments(RotationUpdate treatment, const Block& b) {
  return treatment_for(treatment).moves_present_shape(b);
}

double stress_area(RotationUpdate treatment, const Block& b) {
  return treatment_for(treatment).moves_present_shape(b) ? b.initial_area : b.moments.area;
}

Vec3 stretch_strain(RotationUpdate treatment, const Block& b) {
  return treatment_for(treatment).moves_present_shape(b) ? stretch_from_hencky(b.local_strain)
                                                         : b.local_strain;
}

Vec2 vertex_after(RotationUpdate treatment, const Block& b, std::size_t k, const Vec6& db,
                  const Mat2* column) {
  if (b.fixed) return b.vertices[k];
  return treatment_for(treatment).vertex_after(b, k, db, column);
}

double max_displacement_share(const World& world, const Eigen::VectorXd& d) {
  const LinearT& t = shi_t();
  double largest = 0.0;
  for (const Block& b : world.blocks) {
    if (b.fixed) continue;
    const Vec6 db = increments_of(b, d);
    // A non-finite answer (a solve that broke down) is too large a motion: the step is cut
    // rather than committed (std::max would pass over a nan).
    if (!db.allFinite()) return std::numeric_limits<double>::infinity();
    // The motion relative to the translation (rotation and strain, which the step
    // linearises) against the step limit; the whole motion against the reach the contact
    // search covered.
    const Vec2 translation = db.head<2>();
    for (const Vec2& v : b.vertices) {
      const Vec2 moved = t.at(v - b.moments.centroid) * db;
      largest = std::max({largest, (moved - translation).norm() / b.step_limit, moved.norm() / b.reach});
    }
  }
  return largest;
}

void update_configuration(World& world, const Eigen::VectorXd& d, const StepContext* ctx) {
  treatment_of(world).move_blocks(world, d, ctx);
  remember_rotation_increments(world, d);
}

std::optional<std::size_t> first_inverted_block(const World& world, const Eigen::VectorXd& d,
                                                const StepContext& ctx) {
  const RotationTreatment& treatment = treatment_of(world);
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed || b.rigid) continue;
    const Vec6 db = increments_of(b, d);
    const Mat2 column = solved_rotation_column(&ctx, static_cast<int>(i), db[kR0]);
    if (treatment.turns_inside_out(b, db, column)) return i;
  }
  return std::nullopt;
}

void update_stresses(World& world) {
  const bool in_block_frame = treatment_of(world).keeps_frame();
  for (Block& b : world.blocks) {
    if (b.fixed) continue;
    if (b.plastic) {
      // The material over the total strain the treatment keeps (block frame or global),
      // from the state at the step's start. The step's Newton iteration evaluated this
      // strain up to the increment's turn by r0/2 (material_coupling.cpp), so the return
      // converges as it did there.
      const Vec3& strain = in_block_frame ? b.local_strain : b.strain;
      const MaterialResult r =
          integrate(material_of(world, b), b.material_state, strain, initial_stress4(world, b));
      assert(r.status.converged);
      b.material_state = r.state;
      b.szz = r.stress[kZZ];
      b.branch = r.branch;
      b.stress = in_block_frame ? stress_from_turned_frame(in_plane(r.stress), b.rotation)
                                : in_plane(r.stress);
    } else if (in_block_frame) {
      // Paper Eq. (20) in the block frame, from total strain only (never added), with the
      // initial stress held in that frame; then turned to the global frame.
      b.stress = stress_from_turned_frame(b.initial_stress + elastic_of(world, b) * b.local_strain, b.rotation);
    } else {
      b.stress = b.initial_stress + elastic_of(world, b) * b.strain;
    }
  }
}

void update_velocities(World& world, const Eigen::VectorXd& d, const StepContext& ctx) {
  const RotationTreatment& treatment = treatment_of(world);
  const bool in_block_frame = treatment.keeps_frame();
  for (Block& b : world.blocks) {
    if (b.fixed) continue;
    const Vec6 db = increments_of(b, d);
    const Vec6 v0 = ctx.dynamic_coefficient * b.velocity;
    b.velocity = 2.0 / ctx.dt * db - v0;
    if (treatment.moves_present_shape(b)) {
      // The step's strain unknowns are increments of the spatial velocity gradient's
      // symmetric part D (they move the present shape), so Newmark's rates are D's, kept in
      // the global frame. The Hencky strain's rate, advanced in the block frame as the
      // branch below does, is D only to first order in H; the next step's inertia reads the
      // difference as an acceleration, made again every step: a spinning block at 6 % strain
      // lost angular momentum in proportion to the number of steps (docs/rotating-inertia.md).
      b.local_strain_rate = strain_in_turned_frame(b.velocity.segment<3>(kEx), b.rotation);
    } else if (in_block_frame) {
      // Paper Section 4, steps 6 and 7: the strain rates advance in the block frame with the
      // local increment; step 8: turned to the global frame for the next step's inertia term.
      b.local_strain_rate =
          2.0 / ctx.dt * b.last_local_increment - ctx.dynamic_coefficient * b.local_strain_rate;
      b.velocity.segment<3>(kEx) = strain_from_turned_frame(b.local_strain_rate, b.rotation);
    } else {
      b.local_strain_rate = strain_in_turned_frame(b.velocity.segment<3>(kEx), b.rotation);
    }
  }
}

}  // namespace dda
