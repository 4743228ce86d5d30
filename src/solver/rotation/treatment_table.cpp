// The table of rotation treatments, made from solver/rotation/treatments.def: each line there
// names the function in the treatment's own file that returns it.
#include "solver/rotation/treatment.hpp"

#include <cassert>

#include "kinematics/polygon.hpp"

namespace dda {

#define DDA_TREATMENT(value, name, treatment) const RotationTreatment& treatment();
#include "solver/rotation/treatments.def"
#undef DDA_TREATMENT

namespace {

struct TableRow {
  RotationUpdate update;
  const RotationTreatment& (*treatment)();
};

constexpr TableRow kTreatments[] = {
#define DDA_TREATMENT(value, name, treatment) {RotationUpdate::value, treatment},
#include "solver/rotation/treatments.def"
#undef DDA_TREATMENT
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
