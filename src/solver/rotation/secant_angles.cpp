#include "solver/rotation/secant_angles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kinematics/block_matrices.hpp"
#include "kinematics/point_maps.hpp"

namespace dda {

namespace {

// The farthest vertex's distance from the reference point.
double reach_of(const Block& b) {
  double reach = 0.0;
  for (const Vec2& v : b.vertices) reach = std::max(reach, (v - b.moments.centroid).norm());
  return reach;
}

// The secant column's displacement error at the block's farthest vertex.
double secant_error(const Block& b, double r0, double angle) {
  return 0.5 * reach_of(b) * std::abs(r0) * std::abs(r0 - angle);
}

// The strain rate's share of L^2 = -omega^2 I + omega tr(D) J + D^2 (L = omega J + D, two
// dimensions). The centripetal -omega^2 I follows r0, which the secant angle's own check
// holds (its change moves the farthest vertex by about twice the secant's error): checked
// again here it cost box150 a fifth more solves (7825 against 6539) for rock blocks whose
// strain rates are 1e-3 1/s.
Mat2 strain_rate_share_of_l2(const Spin& s) {
  const Mat2 rate = strain_tensor(s.strain_rate);
  return s.omega * rate.trace() * quarter_turn() + rate * rate;
}

}  // namespace

double spin_error(const Block& b, const Spin& was, const Spin& now, double dt) {
  return 0.5 * dt * dt * reach_of(b) *
         (strain_rate_share_of_l2(now) - strain_rate_share_of_l2(was)).norm();
}

std::vector<double> secant_tolerances(const World& world, const std::vector<Contact>& contacts) {
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
  return tolerance;
}

bool free_secant_off(const World& world, const Block& b, double r0, double angle) {
  return secant_error(b, r0, angle) > kSecantDisplacementShare * world.w0;
}

int follow_secant_angles(const World& world, const std::vector<Contact>& contacts,
                         const Eigen::VectorXd& d, std::vector<double>& angles,
                         std::vector<int>* off) {
  if (off != nullptr) off->clear();
  const std::vector<double> tolerance = secant_tolerances(world, contacts);
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
