#include "solver/secant_angles.hpp"

#include <algorithm>
#include <cmath>

namespace dda {

int follow_secant_angles(const World& world, const std::vector<Contact>& contacts,
                         const Eigen::VectorXd& d, std::vector<double>& angles) {
  const double strict = kSecantDisplacementShare * world.w0;
  std::vector<double> tolerance(world.blocks.size(), strict);
  for (const Contact& c : contacts) {
    if (c.state.mode == ContactMode::Open || !(c.allowed_penetration > 0.0)) continue;
    const double in_contact = std::max(strict, kSecantContactShare * c.allowed_penetration);
    for (const int block : {c.key.vertex_block, c.key.edge_block}) {
      double& t = tolerance[static_cast<std::size_t>(block)];
      t = t == strict ? in_contact : std::min(t, in_contact);
    }
  }
  int moved = 0;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed) continue;
    const double r0 = d[b.first_dof + kR0];
    double reach = 0.0;  // farthest vertex from the reference point
    for (const Vec2& v : b.vertices) reach = std::max(reach, (v - b.moments.centroid).norm());
    if (0.5 * reach * std::abs(r0) * std::abs(r0 - angles[i]) > tolerance[i]) ++moved;
    angles[i] = r0;
  }
  return moved;
}

}  // namespace dda
