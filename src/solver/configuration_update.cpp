#include "solver/configuration_update.hpp"

#include <algorithm>

#include "kinematics/block_matrices.hpp"

namespace dda {
namespace {

Vec6 increments_of(const Block& b, const Eigen::VectorXd& d) { return d.segment<6>(b.first_dof); }

// Original update (Shi 1988): x += T(x - x0) d with the first-order rotation column.
void move_point_original(const LinearT& t, const Vec2& reference, const Vec6& db, Vec2& x) {
  x += t.at(x - reference) * db;
}

}  // namespace

double max_vertex_displacement(const World& world, const Eigen::VectorXd& d) {
  const LinearT t = shi_t();
  double largest = 0.0;
  for (const Block& b : world.blocks) {
    if (b.fixed) continue;
    const Vec6 db = increments_of(b, d);
    for (const Vec2& v : b.vertices) {
      largest = std::max(largest, (t.at(v - b.moments.centroid) * db).norm());
    }
  }
  return largest;
}

void update_configuration(World& world, const Eigen::VectorXd& d) {
  switch (world.control.rotation_update) {
    case RotationUpdate::Original:
      break;  // the only treatment so far; the paper's others arrive with issue 4
  }
  const LinearT t = shi_t();
  // Pins and loads first: they need each block's reference point from the step's start.
  for (Pin& pin : world.pins) {
    const Block& b = world.blocks[pin.block];
    if (!b.fixed) move_point_original(t, b.moments.centroid, increments_of(b, d), pin.current);
  }
  for (PointLoad& load : world.loads) {
    const Block& b = world.blocks[load.block];
    if (!b.fixed) move_point_original(t, b.moments.centroid, increments_of(b, d), load.current);
  }
  for (Block& b : world.blocks) {
    if (b.fixed) continue;
    const Vec6 db = increments_of(b, d);
    const Vec2 reference = b.moments.centroid;
    for (Vec2& v : b.vertices) move_point_original(t, reference, db, v);
    b.rotation += db[kR0];
    b.strain += db.segment<3>(kEx);
    b.moments = polygon_moments(b.vertices);
  }
}

void update_stresses(World& world) {
  for (Block& b : world.blocks) {
    if (!b.fixed) b.stress = b.initial_stress + b.elastic * b.strain;
  }
}

void update_velocities(World& world, const Eigen::VectorXd& d, const StepContext& ctx) {
  for (Block& b : world.blocks) {
    if (b.fixed) continue;
    const Vec6 v0 = ctx.dynamic_coefficient * b.velocity;
    b.velocity = 2.0 / ctx.dt * increments_of(b, d) - v0;
  }
}

}  // namespace dda
