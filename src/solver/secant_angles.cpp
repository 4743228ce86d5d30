#include "solver/secant_angles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dda {

namespace {

// The secant column's displacement error at the block's farthest vertex.
double secant_error(const Block& b, double r0, double angle) {
  double reach = 0.0;  // farthest vertex from the reference point
  for (const Vec2& v : b.vertices) reach = std::max(reach, (v - b.moments.centroid).norm());
  return 0.5 * reach * std::abs(r0) * std::abs(r0 - angle);
}

}  // namespace

bool free_secant_off(const World& world, const Block& b, double r0, double angle) {
  return secant_error(b, r0, angle) > kSecantDisplacementShare * world.w0;
}

int follow_secant_angles(const World& world, const std::vector<Contact>& contacts,
                         const Eigen::VectorXd& d, std::vector<double>& angles,
                         std::vector<int>* off) {
  if (off != nullptr) off->clear();
  // kSecantContactShare of each block's smallest allowance among its closed contacts
  // (infinite for a block in none), never below the free blocks' tolerance.
  const double strict = kSecantDisplacementShare * world.w0;
  std::vector<double> tolerance(world.blocks.size(), std::numeric_limits<double>::infinity());
  for (const Contact& c : contacts) {
    if (c.state.mode == ContactMode::Open || !(c.allowed_penetration > 0.0)) continue;
    for (const int block : {c.key.vertex_block, c.key.edge_block}) {
      double& t = tolerance[static_cast<std::size_t>(block)];
      t = std::min(t, kSecantContactShare * c.allowed_penetration);
    }
  }
  for (double& t : tolerance) t = std::isinf(t) ? strict : std::max(strict, t);
  int moved = 0;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed) continue;
    const double r0 = d[b.first_dof + kR0];
    if (secant_error(b, r0, angles[i]) > tolerance[i]) {
      ++moved;
      if (off != nullptr) off->push_back(static_cast<int>(i));
    }
    angles[i] = r0;
  }
  return moved;
}

}  // namespace dda
