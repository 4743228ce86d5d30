#include "solver/rotation/moved_by_increments.hpp"

#include "kinematics/frames.hpp"
#include "kinematics/polygon.hpp"
#include "solver/rotation/carried_points.hpp"

namespace dda {

Vec2 MovedByIncrements::vertex_after(const Block& b, std::size_t k, const Vec6& db,
                                     const Mat2*) const {
  const Vec2 offset = b.vertices[k] - b.moments.centroid;
  return b.vertices[k] + displacement(b, offset, db);
}

// Every point of every free block moved by displacement(b, x - x0, db), x0 the block's
// reference point at the step's start.
void MovedByIncrements::move_blocks(World& world, const Eigen::VectorXd& d,
                                    const StepContext*) const {
  // Carried points first: they need each block's reference point from the step's start.
  move_carried_points(world, [this, &d](const Block& b, const auto& p) -> Vec2 {
    return p.current + displacement(b, p.current - b.moments.centroid, increments_of(b, d));
  });
  for (Block& b : world.blocks) {
    if (b.fixed) continue;
    const Vec6 db = increments_of(b, d);
    const Vec2 reference = b.moments.centroid;
    for (Vec2& v : b.vertices) v += displacement(b, v - reference, db);
    b.translation += db.head<2>();
    b.rotation += db[kR0];
    b.strain += db.segment<3>(kEx);
    // Reported only: the global total strain seen from the block frame.
    b.local_strain = strain_in_turned_frame(b.strain, b.rotation);
    b.moments = polygon_moments(b.vertices);
  }
}

}  // namespace dda
