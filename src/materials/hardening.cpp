#include "materials/hardening.hpp"

#include <algorithm>
#include <cstddef>

namespace dda {

namespace {

// Index i of the segment [table[i], table[i+1]) holding e, for 0 < e-position < last.
std::size_t segment_of(std::span<const HardeningPoint> table, double e) {
  const auto above = std::upper_bound(
      table.begin(), table.end(), e, [](double x, const HardeningPoint& p) { return x < p.eps_p; });
  return static_cast<std::size_t>(above - table.begin()) - 1;
}

}  // namespace

double CohesionLaw::value(double e) const {
  if (table_.empty()) return constant_;
  if (e <= table_.front().eps_p) return table_.front().cohesion;
  if (e >= table_.back().eps_p) return table_.back().cohesion;
  const std::size_t i = segment_of(table_, e);
  const HardeningPoint& a = table_[i];
  const HardeningPoint& b = table_[i + 1];
  const double t = (e - a.eps_p) / (b.eps_p - a.eps_p);
  return a.cohesion + t * (b.cohesion - a.cohesion);
}

double CohesionLaw::slope(double e) const {
  if (table_.size() < 2) return 0.0;
  if (e < table_.front().eps_p || e >= table_.back().eps_p) return 0.0;
  const std::size_t i = segment_of(table_, e);
  const HardeningPoint& a = table_[i];
  const HardeningPoint& b = table_[i + 1];
  return (b.cohesion - a.cohesion) / (b.eps_p - a.eps_p);
}

}  // namespace dda
