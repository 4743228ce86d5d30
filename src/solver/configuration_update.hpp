// Stages after the solve: how far the step moves the blocks (for the displacement-ratio
// check), the configuration update (by the rotation treatment, solver/rotation/), and the
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
// the treatment of world.control.rotation_update (its move_blocks, solver/rotation/; paper
// Sections 2-4), then records each block's r0 as its last_rotation_increment. `ctx`: the
// step's T, by which finite_rotation_polar places its deformable blocks (without ctx, the
// secant column at the block's own r0, the exact rotation), so that every point goes
// exactly to x + T d.
void update_configuration(World& world, const Eigen::VectorXd& d,
                          const StepContext* ctx = nullptr);

// Whether block b's step moves its present shape, F' = (I + r0 a + dE) F: the deformable
// blocks of finite_rotation_polar (RotationTreatment::moves_present_shape). Their velocities
// are then those of the spatial velocity gradient (strain rates: its symmetric part D,
// global frame), and their inertia's quadratic terms are spatial_rotating_inertia_force's.
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

// Where vertex k of block b will be after update_configuration with the block's increments
// db, without moving anything (the treatment's vertex_after; tests check that the two agree).
// (`column`: the rotation column of the block's T, as update_configuration's; null: the
// secant column at its own r0.)
Vec2 vertex_after(RotationUpdate treatment, const Block& b, std::size_t k, const Vec6& db,
                  const Mat2* column = nullptr);

// The first deformable block (not fixed, not rigid) that the increments `d` would turn inside
// out: its area after the step (the treatment's turns_inside_out, with ctx's rotation
// columns) at most zero, or not finite. None: nullopt. A block far too soft for its load is crushed
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
