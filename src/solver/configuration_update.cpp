#include "solver/configuration_update.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "kinematics/block_matrices.hpp"
#include "kinematics/frames.hpp"
#include "kinematics/point_maps.hpp"
#include "materials/material.hpp"

namespace dda {
namespace {

Vec6 increments_of(const Block& b, const Eigen::VectorXd& d) { return d.segment<6>(b.first_dof); }

// The material points that ride on blocks (pins, point loads, monitors: each has `block`,
// `initial` and `current`): every one on a free block set to where(block, point).
template <class Where>
void move_carried_points(World& world, Where where) {
  const auto move = [&world, &where](auto& points) {
    for (auto& p : points) {
      const Block& b = world.blocks[static_cast<std::size_t>(p.block)];
      if (!b.fixed) p.current = where(b, p);
    }
  };
  move(world.pins);
  move(world.loads);
  move(world.monitors);
}

// ---- treatments that move points by the step's increments (original, second order,
// post-adjustment): strains added in the global frame (paper Eq. 13) ----

// Every point of every free block moved by displacement(b, x - x0, db), x0 the block's
// reference point at the step's start (sin_variable's T' also reads the block).
template <class Displacement>
void move_by_increments(World& world, const Eigen::VectorXd& d, Displacement displacement) {
  // Carried points first: they need each block's reference point from the step's start.
  move_carried_points(world, [&d, &displacement](const Block& b, const auto& p) -> Vec2 {
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

// ---- treatments that keep the strain in the block frame (paper Sections 3 and 4) ----

// The frame angle halfway through the step just taken; valid once the update has added the
// step's r0 to b.rotation. The step's strain increment is measured while the block turns
// from r to r + r0; a strain whose local rate is steady over the step averages, in the global
// frame, to the local increment turned by the mid-step angle (its deviatoric part turns with
// 2 theta, and the mean of exp(2 i theta) over the step points at the mid angle). The start
// or the end angle (the paper's Eq. 17 uses the end) is off by r0/2, an error of order
// r0 x the increment; the mid angle leaves r0^2 x the increment and is symmetric in time.
double mid_step_frame_angle(const Block& b, const Vec6& db) { return b.rotation - 0.5 * db[kR0]; }

// The step's strain increment in the block frame (paper Eq. 17, sign corrected), for a
// block whose rotation the update has advanced: at the mid-step angle, or under `paper` at
// the end-of-step angle the paper prints.
Vec3 local_increment(RotationUpdate treatment, const Block& b, const Vec6& db) {
  const double angle =
      treatment == RotationUpdate::Paper ? b.rotation : mid_step_frame_angle(b, db);
  return strain_in_turned_frame(db.segment<3>(kEx), angle);
}

bool places_by_polar(RotationUpdate treatment, const Block& b) {
  return treatment == RotationUpdate::FiniteRotationPolar && !b.fixed && !b.rigid;
}

// x = xc + A (X - Xc): the block's map from its initial configuration.
Vec2 place(const Block& b, const Mat2& a, const Vec2& material_point) {
  return b.initial_centroid + b.translation + a * (material_point - b.initial_centroid);
}

// Accumulates translation, rotation (Eqs. 14, 15) and local strain (Eqs. 16, 17), derives the
// global strain (Eq. 18), then places vertices, pins and loads from their material points by
// the linear part frame_map(r, e^) (consistent Eq. 19, or as printed). The current centroid
// of a homogeneously deformed polygon is the image of the initial one, so xc (the reference
// point of the next step) stays the centroid.
template <class FrameMap>
void rebuild_in_frame(World& world, const Eigen::VectorXd& d, const StepContext* ctx,
                      FrameMap frame_map) {
  std::vector<Mat2> maps(world.blocks.size(), Mat2::Identity());
  const RotationUpdate treatment = world.control.rotation_update;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    Block& b = world.blocks[i];
    if (b.fixed) continue;
    const Vec6 db = increments_of(b, d);
    b.translation += db.head<2>();
    if (places_by_polar(treatment, b)) {
      const PolarStep p =
          polar_step(b, db, solved_rotation_column(ctx, static_cast<int>(i), db[kR0]));
      b.last_local_increment = p.local_strain - b.local_strain;
      b.rotation = p.rotation;
      b.local_strain = p.local_strain;
      b.strain = strain_from_turned_frame(b.local_strain, b.rotation);
      maps[i] = p.map;
    } else {
      b.rotation += db[kR0];
      b.last_local_increment = local_increment(treatment, b, db);
      b.local_strain += b.last_local_increment;
      b.strain = strain_from_turned_frame(b.local_strain, b.rotation);
      maps[i] = frame_map(b.rotation, b.local_strain);
    }
    for (std::size_t k = 0; k < b.vertices.size(); ++k) {
      b.vertices[k] = place(b, maps[i], b.initial_vertices[k]);
    }
    b.moments = polygon_moments(b.vertices);
  }
  move_carried_points(world, [&maps](const Block& b, const auto& p) -> Vec2 {
    return place(b, maps[static_cast<std::size_t>(p.block)], p.initial);
  });
}


// sin_variable (Cheng and Zhang, paper Eqs. 9-12): points move by T' d' with the same T'
// as the step (the last step's r0 inside it) and d' = (u0, v0, sin r0, ex, ey, gxy).
Vec2 sine_column_displacement(const Block& b, const Vec2& offset, const Vec6& db) {
  Vec6 sine_db = db;
  sine_db[kR0] = std::sin(db[kR0]);
  return t_with_rotation_column(sine_rotation_column(b.last_rotation_increment)).at(offset) *
         sine_db;
}

void remember_rotation_increments(World& world, const Eigen::VectorXd& d) {
  for (Block& b : world.blocks) {
    if (!b.fixed) b.last_rotation_increment = d[b.first_dof + kR0];
  }
}

void move_blocks(World& world, const Eigen::VectorXd& d, const StepContext* ctx) {
  switch (world.control.rotation_update) {
    case RotationUpdate::Original: {
      // Shi 1988: x += T(x - x0) d with the first-order rotation column (paper Eq. 2).
      const LinearT t = shi_t();
      move_by_increments(world, d, [&t](const Block&, const Vec2& offset, const Vec6& db) {
        return Vec2(t.at(offset) * db);
      });
      return;
    }
    case RotationUpdate::SecondOrder:  // Eq. 8 with cos r0 = 1 - r0^2/2, sin r0 = r0
      move_by_increments(world, d, [](const Block&, const Vec2& offset, const Vec6& db) {
        return second_order_displacement(offset, db);
      });
      return;
    case RotationUpdate::PostAdjustment:  // Eq. 8, exact, after the open-close loop converged
      move_by_increments(world, d, [](const Block&, const Vec2& offset, const Vec6& db) {
        return finite_rotation_displacement(offset, db);
      });
      return;
    case RotationUpdate::LocalFrame:  // Eq. 19, consistent: x = xc + R(r)(I + E^)(X - Xc)
    case RotationUpdate::Paper:       // the same, the increment turned by the end angle
      rebuild_in_frame(world, d, ctx, frame_map);
      return;
    case RotationUpdate::LocalFrameAsPrinted:  // Eq. 19 as printed: x = xc + (R + E)(X - Xc)
      rebuild_in_frame(world, d, ctx, frame_map_as_printed);
      return;
    case RotationUpdate::SinVariable:  // T' d' with the step's T' (Eqs. 10-12)
      move_by_increments(world, d, sine_column_displacement);
      return;
    case RotationUpdate::FiniteRotation:  // local_frame's map; the step used the secant T
    case RotationUpdate::FiniteRotationPolar:  // deformable blocks: the step's own map, polar
      rebuild_in_frame(world, d, ctx, frame_map);
      return;
  }
}

}  // namespace

namespace {

// The map F' of polar_step alone (vertex_after places points by it; the decomposition and
// its logarithm are the state's, not needed there).
Mat2 polar_map(const Block& b, const Vec6& db, const Mat2& column) {
  return (Mat2::Identity() + db[kR0] * column + strain_tensor(db.segment<3>(kEx))) *
         hencky_frame_map(b.rotation, b.local_strain);
}

// The rotation column given, or without one the secant column at r0 (the exact rotation).
Mat2 column_or_secant(const Mat2* column, double r0) {
  return column != nullptr ? *column : secant_rotation_column(r0);
}

}  // namespace

PolarStep polar_step(const Block& b, const Vec6& db, const Mat2& column) {
  const Mat2 after = polar_map(b, db, column);
  const PolarDecomposition p = polar_decomposition(after, b.rotation + db[kR0]);
  return {p.angle, hencky_from_stretch(p.strain), after};
}

bool spatial_increments(RotationUpdate treatment, const Block& b) {
  return places_by_polar(treatment, b);
}

double stress_area(RotationUpdate treatment, const Block& b) {
  return places_by_polar(treatment, b) ? b.initial_area : b.moments.area;
}

Vec3 stretch_strain(RotationUpdate treatment, const Block& b) {
  return places_by_polar(treatment, b) ? stretch_from_hencky(b.local_strain) : b.local_strain;
}

Mat2 solved_rotation_column(const StepContext* ctx, int index, double r0) {
  if (ctx == nullptr) return secant_rotation_column(r0);
  return rotation_column(step_t(*ctx, index));
}

Vec3 block_frame_increment(const Block& b, const Vec6& db) {
  return strain_in_turned_frame(db.segment<3>(kEx), b.rotation + 0.5 * db[kR0]);
}

Vec3 block_frame_increment(RotationUpdate treatment, const Block& b, const Vec6& db,
                           const Mat2* column) {
  if (treatment == RotationUpdate::Paper) {
    return strain_in_turned_frame(db.segment<3>(kEx), b.rotation + db[kR0]);
  }
  if (places_by_polar(treatment, b)) {
    return polar_step(b, db, column_or_secant(column, db[kR0])).local_strain - b.local_strain;
  }
  return block_frame_increment(b, db);
}

Vec2 vertex_after(RotationUpdate treatment, const Block& b, std::size_t k, const Vec6& db,
                  const Mat2* column) {
  if (b.fixed) return b.vertices[k];
  if (places_by_polar(treatment, b)) {
    return b.initial_centroid + b.translation + db.head<2>() +
           polar_map(b, db, column_or_secant(column, db[kR0])) *
               (b.initial_vertices[k] - b.initial_centroid);
  }
  const Vec2 offset = b.vertices[k] - b.moments.centroid;
  switch (treatment) {
    case RotationUpdate::Original: return b.vertices[k] + shi_t().at(offset) * db;
    case RotationUpdate::SecondOrder: return b.vertices[k] + second_order_displacement(offset, db);
    case RotationUpdate::PostAdjustment:
      return b.vertices[k] + finite_rotation_displacement(offset, db);
    case RotationUpdate::SinVariable: return b.vertices[k] + sine_column_displacement(b, offset, db);
    case RotationUpdate::LocalFrame:
    case RotationUpdate::LocalFrameAsPrinted:
    case RotationUpdate::FiniteRotation:
    case RotationUpdate::FiniteRotationPolar:  // (its rigid blocks)
    case RotationUpdate::Paper: {
      // rebuild_in_frame's rule: the step's r0 and strain increment (turned by the
      // mid-step angle, or the end angle under `paper`) added, then x = xc + A (X - Xc).
      const double rotation = b.rotation + db[kR0];
      const Vec3 local_strain = b.local_strain + block_frame_increment(treatment, b, db);
      const Mat2 a = treatment == RotationUpdate::LocalFrameAsPrinted
                         ? frame_map_as_printed(rotation, local_strain)
                         : frame_map(rotation, local_strain);
      return b.initial_centroid + b.translation + db.head<2>() +
             a * (b.initial_vertices[k] - b.initial_centroid);
    }
  }
  return b.vertices[k];
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
  move_blocks(world, d, ctx);
  remember_rotation_increments(world, d);
}

std::optional<std::size_t> first_inverted_block(const World& world, const Eigen::VectorXd& d,
                                                const StepContext& ctx) {
  const RotationUpdate treatment = world.control.rotation_update;
  Polygon after;
  for (std::size_t i = 0; i < world.blocks.size(); ++i) {
    const Block& b = world.blocks[i];
    if (b.fixed || b.rigid) continue;
    const Vec6 db = increments_of(b, d);
    const Mat2 column = solved_rotation_column(&ctx, static_cast<int>(i), db[kR0]);
    if (places_by_polar(treatment, b)) {
      // Placed by one linear map from the initial polygon: its area is det(map) x A0.
      const double det = polar_map(b, db, column).determinant();
      if (!(det > 0.0)) return i;
      continue;
    }
    after.resize(b.vertices.size());
    for (std::size_t k = 0; k < after.size(); ++k) after[k] = vertex_after(treatment, b, k, db, &column);
    const double area = signed_area(after);
    if (!(area > 0.0)) return i;  // also a nan
  }
  return std::nullopt;
}

void update_stresses(World& world) {
  const bool in_block_frame = keeps_block_frame(world.control.rotation_update);
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
  const bool in_block_frame = keeps_block_frame(world.control.rotation_update);
  for (Block& b : world.blocks) {
    if (b.fixed) continue;
    const Vec6 db = increments_of(b, d);
    const Vec6 v0 = ctx.dynamic_coefficient * b.velocity;
    b.velocity = 2.0 / ctx.dt * db - v0;
    if (places_by_polar(world.control.rotation_update, b)) {
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
