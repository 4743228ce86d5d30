// Cohesion as a piecewise-linear function of the equivalent plastic strain eps_p, from a
// table [[eps_p, cohesion], ...] with eps_p strictly increasing (validate_material checks),
// constant beyond both ends. An empty table means a constant cohesion.
#pragma once

#include <span>

namespace dda {

struct HardeningPoint {
  double eps_p = 0.0;     // equivalent plastic strain (see material.hpp for its definition)
  double cohesion = 0.0;  // Pa
};

// A view of the table (it does not own it) plus the constant used when the table is empty.
class CohesionLaw {
 public:
  CohesionLaw(std::span<const HardeningPoint> table, double constant_cohesion)
      : table_(table), constant_(constant_cohesion) {}

  // c(eps_p).
  double value(double eps_p) const;

  // dc/deps_p of the segment that eps_p lies in. At a table point the segment to its right
  // is used: eps_p only grows, so that is the segment a return is moving into. Zero beyond
  // the ends and for a constant cohesion.
  double slope(double eps_p) const;

  bool constant() const { return table_.size() < 2; }

 private:
  std::span<const HardeningPoint> table_;
  double constant_;
};

}  // namespace dda
