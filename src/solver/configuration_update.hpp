// Stages after the solve: how far the step moves the blocks (for the displacement-ratio
// check), the configuration update (one switch over the rotation treatment), and the
// strains, stresses and velocities that follow from the step's increments d.
#pragma once

#include <optional>

#include <Eigen/Dense>

#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// The largest share of its limits that any vertex of a free block would move with
// increments d: its motion relative to the block's translation against Block::step_limit,
// its whole motion against Block::reach. Above 1, the step moves too far.
double max_displacement_share(const World& world, const Eigen::VectorXd& d);

// Moves vertices, pins and point loads and accumulates translation, rotation and strain by
// the treatment in world.control.rotation_update (one switch; paper Sections 2-4):
//   original, second_order, post_adjustment: every point x += displacement(x - x0, d)
//     (Eq. 2 with the first-order T; Eq. 8 with cos r = 1 - r^2/2, sin r = r; Eq. 8 exact),
//     strains added in the global frame (Eq. 13);
//   local_frame, local_frame_as_printed: strain increments turned into the block frame and
//     added there (Eqs. 16-17), every point placed from its material point at the start by
//     x = xc + A (X - Xc) (Eq. 19: A = R(r)(I + E^), or as printed A = R(r) + R E^ R^T).
//   sin_variable: points moved by T' d' with the step's T' (Cheng and Zhang, Eqs. 10-12;
//     d holds r0 = asin of the solved unknown), strains added in the global frame;
//   finite_rotation: as local_frame (the step itself used the secant rotation column).
// Every treatment then records each block's r0 as its last_rotation_increment.
// finite_rotation_polar places its deformable blocks by the rotation column of the T each
// was solved with (ctx's; without ctx, the secant column at the block's own r0, the exact
// rotation), so that every point goes exactly to x + T d.
void update_configuration(World& world, const Eigen::VectorXd& d,
                          const StepContext* ctx = nullptr);

// The step's strain increment db[ex, ey, gxy] (global frame) in block b's frame, turned by
// the mid-step angle b.rotation + r0 / 2, for a block not yet updated (the update takes the
// same angle from its updated rotation). The local-frame treatments accumulate it.
Vec3 block_frame_increment(const Block& b, const Vec6& db);
// The same for the given treatment: finite_rotation_polar's deformable blocks take the change
// of the polar decomposition's strain over the step instead.
// (`column`: the rotation column of the block's T, as update_configuration's; null: the
// secant column at its own r0.)
Vec3 block_frame_increment(RotationUpdate treatment, const Block& b, const Vec6& db,
                           const Mat2* column = nullptr);

// finite_rotation_polar, a free deformable block: the map the step applies to its present
// shape, F' = (I + r0 a + dE) F, with F = R(r) exp(H) at the step's start (H its block-frame
// Hencky strain), a the rotation column of the block's T (the secant column at r0 makes
// I + r0 a = R(r0) exactly) and dE the global-frame strain increment; and the polar
// decomposition F' = R(r') U': the block's rotation r' (nearest r + r0) and block-frame
// Hencky strain H' = ln U' after the step (docs/large-strain.md).
struct PolarStep {
  double rotation = 0.0;
  Vec3 local_strain = Vec3::Zero();  // H' = ln U'
  Mat2 map = Mat2::Identity();       // F'
};
PolarStep polar_step(const Block& b, const Vec6& db, const Mat2& column);

// Whether block b's step moves its present shape, F' = (I + r0 a + dE) F: the deformable
// blocks of finite_rotation_polar. Their velocities are then those of the spatial velocity
// gradient (strain rates: its symmetric part D, global frame), and their inertia's quadratic
// terms are spatial_rotating_inertia_force's.
bool spatial_increments(RotationUpdate treatment, const Block& b);

// The block-frame stretch U - I of block b (the Biot strain): its local_strain, which
// finite_rotation_polar keeps as the Hencky strain ln U and the other treatments as U - I.
Vec3 stretch_strain(RotationUpdate treatment, const Block& b);

// The area block b's stress acts over in the step's strain columns and its strain energy
// is counted over: its present area, the stress being Cauchy's; under
// finite_rotation_polar a deformable block's initial area, its stress being the
// Kirchhoff stress J s (J = area / initial area), the one that does work on the Hencky
// strain (docs/large-strain.md).
double stress_area(RotationUpdate treatment, const Block& b);

// The rotation column block `index` was solved with: that of ctx's T; without ctx, the
// secant column at r0.
Mat2 solved_rotation_column(const StepContext* ctx, int index, double r0);

// Where vertex k of block b will be after update_configuration with the block's increments
// db, without moving anything (the same rule per treatment; tests check that the two agree).
Vec2 vertex_after(RotationUpdate treatment, const Block& b, std::size_t k, const Vec6& db,
                  const Mat2* column = nullptr);

// The first deformable block (not fixed, not rigid) that the increments `d` would turn inside
// out: its area after the step (its vertices by vertex_after, with ctx's rotation columns)
// at most zero, or not finite. None: nullopt. A block far too soft for its load is crushed
// through zero area over a few steps; its polar decomposition (or its Jacobian) has no
// meaning there, and committing it wrote nan into the state.
std::optional<std::size_t> first_inverted_block(const World& world, const Eigen::VectorXd& d,
                                                const StepContext& ctx);

// Stress from total strain (elastic, never added): s = s_initial + D e in the global frame,
// or, for the local-frame treatments, s_initial + D e^ in the block frame turned to the
// global frame (Eq. 20). Run after update_configuration.
void update_stresses(World& world);

// Shi's velocity update v1 = 2 d / dt - v0, with v0 the (dynamic-coefficient scaled)
// velocity that entered the step. The local-frame treatments advance the strain rates in the
// block frame instead and turn them to the global frame (paper Section 4, steps 6-8). Run
// after update_configuration (it reads the frame angle the update reached).
void update_velocities(World& world, const Eigen::VectorXd& d, const StepContext& ctx);

}  // namespace dda
