// finite_rotation_polar, the default: finite_rotation's step, but each deformable block
// placed by the map the step's T applied, F' = (I + r0 a + dE) F, its rotation and
// block-frame Hencky strain ln U taken from the polar decomposition F' = R(r) U, and its
// stress Kirchhoff's over its initial area (docs/large-strain.md). Rigid blocks are placed as
// under finite_rotation.
#include "kinematics/block_matrices.hpp"
#include "kinematics/frames.hpp"
#include "kinematics/point_maps.hpp"
#include "solver/rotation/rotation_columns.hpp"
#include "solver/rotation/secant_column.hpp"

namespace dda {
namespace {

// The map F' = (I + r0 a + dE) F a free deformable block's step applies to its present
// shape, with F = R(r) exp(H) at the step's start (H its block-frame Hencky strain), a the
// rotation column of the block's T (the secant column at r0 makes I + r0 a = R(r0) exactly)
// and dE the global-frame strain increment.
Mat2 polar_map(const Block& b, const Vec6& db, const Mat2& column) {
  return (Mat2::Identity() + db[kR0] * column + strain_tensor(db.segment<3>(kEx))) *
         hencky_frame_map(b.rotation, b.local_strain);
}

// The polar decomposition F' = R(r') U': the block's rotation r' (nearest r + r0) and
// block-frame Hencky strain H' = ln U' after the step.
struct PolarStep {
  double rotation = 0.0;
  Vec3 local_strain = Vec3::Zero();  // H' = ln U'
  Mat2 map = Mat2::Identity();       // F'
};

PolarStep polar_step(const Block& b, const Vec6& db, const Mat2& column) {
  const Mat2 after = polar_map(b, db, column);
  const PolarDecomposition p = polar_decomposition(after, b.rotation + db[kR0]);
  return {p.angle, hencky_from_stretch(p.strain), after};
}

// The rotation column given, or without one the secant column at r0 (the exact rotation).
Mat2 column_or_secant(const Mat2* column, double r0) {
  return column != nullptr ? *column : secant_rotation_column(r0);
}

class FiniteRotationPolar final : public SecantColumn {
 public:
  bool moves_present_shape(const Block& b) const override { return !b.fixed && !b.rigid; }

  Vec2 vertex_after(const Block& b, std::size_t k, const Vec6& db,
                    const Mat2* column) const override {
    if (!moves_present_shape(b)) return SecantColumn::vertex_after(b, k, db, column);
    return b.initial_centroid + b.translation + db.head<2>() +
           polar_map(b, db, column_or_secant(column, db[kR0])) *
               (b.initial_vertices[k] - b.initial_centroid);
  }

  // A deformable block's: the change of the polar decomposition's strain over the step.
  Vec3 block_frame_increment(const Block& b, const Vec6& db, const Mat2* column) const override {
    if (!moves_present_shape(b)) return SecantColumn::block_frame_increment(b, db, column);
    return polar_step(b, db, column_or_secant(column, db[kR0])).local_strain - b.local_strain;
  }

  // A deformable block placed by the rotation column of the T it was solved with (ctx's;
  // without ctx, the secant column at its own r0, the exact rotation), so that every point
  // goes exactly to x + T d.
  Mat2 advance_block(Block& b, const Vec6& db, const StepContext* ctx, int index) const override {
    if (!moves_present_shape(b)) return SecantColumn::advance_block(b, db, ctx, index);
    const PolarStep p = polar_step(b, db, solved_rotation_column(ctx, index, db[kR0]));
    b.last_local_increment = p.local_strain - b.local_strain;
    b.rotation = p.rotation;
    b.local_strain = p.local_strain;
    b.strain = strain_from_turned_frame(b.local_strain, b.rotation);
    return p.map;
  }

  // Placed by one linear map from the initial polygon: its area is det(map) x A0.
  bool turns_inside_out(const Block& b, const Vec6& db, const Mat2& column) const override {
    if (!moves_present_shape(b)) return SecantColumn::turns_inside_out(b, db, column);
    const double det = polar_map(b, db, column).determinant();
    return !(det > 0.0);
  }
};

}  // namespace

const RotationTreatment& finite_rotation_polar_treatment() {
  static const FiniteRotationPolar treatment;
  return treatment;
}

}  // namespace dda
