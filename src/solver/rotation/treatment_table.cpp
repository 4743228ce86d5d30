// The table of rotation treatments: one line per treatment, naming the function in its own
// file that returns it. A new treatment is its file and its line here (and its scene name,
// RotationUpdate and kRotationUpdateNames in solver/scene.hpp).
#include "solver/rotation/treatment.hpp"

#include <cassert>

#include "kinematics/polygon.hpp"

namespace dda {

const RotationTreatment& original_treatment();
const RotationTreatment& second_order_treatment();
const RotationTreatment& post_adjustment_treatment();
const RotationTreatment& sin_variable_treatment();
const RotationTreatment& local_frame_treatment();
const RotationTreatment& local_frame_as_printed_treatment();
const RotationTreatment& finite_rotation_treatment();
const RotationTreatment& finite_rotation_polar_treatment();
const RotationTreatment& paper_treatment();

namespace {

struct TableRow {
  RotationUpdate update;
  const RotationTreatment& (*treatment)();
};

constexpr TableRow kTreatments[] = {
    {RotationUpdate::Original, original_treatment},
    {RotationUpdate::SecondOrder, second_order_treatment},
    {RotationUpdate::PostAdjustment, post_adjustment_treatment},
    {RotationUpdate::SinVariable, sin_variable_treatment},
    {RotationUpdate::LocalFrame, local_frame_treatment},
    {RotationUpdate::LocalFrameAsPrinted, local_frame_as_printed_treatment},
    {RotationUpdate::FiniteRotation, finite_rotation_treatment},
    {RotationUpdate::FiniteRotationPolar, finite_rotation_polar_treatment},
    {RotationUpdate::Paper, paper_treatment},
};

}  // namespace

const RotationTreatment& treatment_for(RotationUpdate u) {
  for (const TableRow& row : kTreatments) {
    if (row.update == u) return row.treatment();
  }
  assert(false && "a RotationUpdate without a row in kTreatments");
  return original_treatment();
}

// Any treatment: the block's vertices placed where the update will put them, and the area of
// that polygon.
bool RotationTreatment::turns_inside_out(const Block& b, const Vec6& db, const Mat2& column) const {
  Polygon after(b.vertices.size());
  for (std::size_t k = 0; k < after.size(); ++k) after[k] = vertex_after(b, k, db, &column);
  const double area = signed_area(after);
  return !(area > 0.0);  // also a nan
}

}  // namespace dda
