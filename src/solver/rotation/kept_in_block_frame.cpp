#include "solver/rotation/kept_in_block_frame.hpp"

#include <vector>

#include "kinematics/frames.hpp"
#include "kinematics/point_maps.hpp"
#include "kinematics/polygon.hpp"
#include "solver/rotation/carried_points.hpp"

namespace dda {
namespace {

// The frame angle halfway through the step just taken; valid once the update has added the
// step's r0 to b.rotation. The step's strain increment is measured while the block turns
// from r to r + r0; a strain whose local rate is steady over the step averages, in the global
// frame, to the local increment turned by the mid-step angle (its deviatoric part turns with
// 2 theta, and the mean of exp(2 i theta) over the step points at the mid angle). The start
// or the end angle (the paper's Eq. 17 uses the end) is off by r0/2, an error of order
// r0 x the increment; the mid angle leaves r0^2 x the increment and is symmetric in time.
double mid_step_frame_angle(const Block& b, const Vec6& db) { return b.rotation - 0.5 * db[kR0]; }

// x = xc + A (X - Xc): the block's map from its initial configuration.
Vec2 place(const Block& b, const Mat2& a, const Vec2& material_point) {
  return b.initial_centroid + b.translation + a * (material_point - b.initial_centroid);
}

}  // namespace

Vec3 block_frame_increment(const Block& b, const Vec6& db) {
  return strain_in_turned_frame(db.segment<3>(kEx), b.rotation + 0.5 * db[kR0]);
}

Mat2 KeptInBlockFrame::map_from_initial(double r, const Vec3& local_strain) const {
  return frame_map(r, local_strain);
}

Vec3 KeptInBlockFrame::increment_in_frame(const Block& b, const Vec6& db) const {
  return strain_in_turned_frame(db.segment<3>(kEx), mid_step_frame_angle(b, db));
}

Vec3 KeptInBlockFrame::block_frame_increment(const Block& b, const Vec6& db, const Mat2*) const {
  return dda::block_frame_increment(b, db);
}

Mat2 KeptInBlockFrame::advance_block(Block& b, const Vec6& db, const StepContext*, int) const {
  b.rotation += db[kR0];
  b.last_local_increment = increment_in_frame(b, db);
  b.local_strain += b.last_local_increment;
  b.strain = strain_from_turned_frame(b.local_strain, b.rotation);
  return map_from_initial(b.rotation, b.local_strain);
}

Vec2 KeptInBlockFrame::vertex_after(const Block& b, std::size_t k, const Vec6& db,
                                    const Mat2*) const {
  // move_blocks' rule: the step's r0 and strain increment added, then x = xc + A (X - Xc).
  const double rotation = b.rotation + db[kR0];
  const Vec3 local_strain = b.local_strain + block_frame_increment(b, db, nullptr);
  const Mat2 a = map_from_initial(rotation, local_strain);
  return b.initial_centroid + b.translation + db.head<2>() +
         a * (b.initial_vertices[k] - b.initial_centroid);
}

// Accumulates translation, rotation and block-frame strain, derives the global strain
// (Eq. 18), then places vertices, pins and loads from their material points by the map A.
// The current centroid of a homogeneously deformed polygon is the image of the initial one,
// so xc (the reference point of the next step) stays the centroid.
void KeptInBlockFrame::move_blocks(World& world, const Eigen::VectorXd& d,
                                   const StepContext* ctx) const {
  std::vector<Mat2> maps(world.blocks.size(), Mat2::Identity());
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    Block& b = world.blocks[i];
    if (b.fixed) continue;
    const Vec6 db = increments_of(b, d);
    b.translation += db.head<2>();
    maps[i] = advance_block(b, db, ctx, static_cast<int>(i));
    for (std::size_t k = 0; k < b.vertices.size(); ++k) {
      b.vertices[k] = place(b, maps[i], b.initial_vertices[k]);
    }
    b.moments = polygon_moments(b.vertices);
  }
  move_carried_points(world, [&maps](const Block& b, const auto& p) -> Vec2 {
    return place(b, maps[static_cast<std::size_t>(p.block)], p.initial);
  });
}

}  // namespace dda
