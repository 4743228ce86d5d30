// Stages after the solve: how far the step moves the blocks (for the displacement-ratio
// check), the configuration update (one switch over the rotation treatment), and the
// strains, stresses and velocities that follow from the step's increments d.
#pragma once

#include <Eigen/Dense>

#include "solver/step_context.hpp"
#include "solver/world.hpp"

namespace dda {

// The largest distance any vertex of a free block would move with increments d (m).
double max_vertex_displacement(const World& world, const Eigen::VectorXd& d);

// Moves vertices, pins and point loads and accumulates rotation and strain.
// Original (Shi): every point x += T(x) d with the first-order T; strains added globally.
void update_configuration(World& world, const Eigen::VectorXd& d);

// Stress from total strain (elastic): s = s_initial + D e.
void update_stresses(World& world);

// Shi's velocity update v1 = 2 d / dt - v0, with v0 the (dynamic-coefficient scaled)
// velocity that entered the step.
void update_velocities(World& world, const Eigen::VectorXd& d, const StepContext& ctx);

}  // namespace dda
