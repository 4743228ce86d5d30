#include "solver/base_motion.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace dda {
namespace {

// The sine's active window in history time: [0, end].
double sine_end(const BaseMotion& m) {
  return m.cycles ? *m.cycles / m.frequency : std::numeric_limits<double>::infinity();
}

// Integral of the record's linear interpolant over history time [a, b] (zero outside it).
Vec2 record_integral(const BaseMotion& m, double a, double b) {
  Vec2 sum = Vec2::Zero();
  for (std::size_t k = 0; k + 1 < m.times.size(); ++k) {
    const double t0 = m.times[k], t1 = m.times[k + 1];
    const double lo = std::max(a, t0), hi = std::min(b, t1);
    if (hi <= lo) continue;
    auto at = [&](double t) {
      const double s = (t - t0) / (t1 - t0);
      return Vec2((1.0 - s) * m.accelerations[k] + s * m.accelerations[k + 1]);
    };
    sum += 0.5 * (at(lo) + at(hi)) * (hi - lo);  // the trapezoid is exact for a linear piece
  }
  return sum;
}

}  // namespace

Vec2 base_acceleration(const BaseMotion& m, double t) {
  const double h = t - m.start;
  if (m.is_sine) {
    if (h < 0.0 || h > sine_end(m)) return Vec2::Zero();
    return m.amplitude * std::sin(2.0 * M_PI * m.frequency * h);
  }
  if (m.times.empty() || h < m.times.front() || h > m.times.back()) return Vec2::Zero();
  const auto next = std::upper_bound(m.times.begin(), m.times.end(), h);
  if (next == m.times.end()) return m.accelerations.back();
  const std::size_t k = static_cast<std::size_t>(next - m.times.begin());
  const double s = (h - m.times[k - 1]) / (m.times[k] - m.times[k - 1]);
  return (1.0 - s) * m.accelerations[k - 1] + s * m.accelerations[k];
}

Vec2 mean_base_acceleration(const BaseMotion& m, double t0, double t1) {
  assert(t1 > t0);
  const double a = t0 - m.start, b = t1 - m.start;
  if (m.is_sine) {
    const double lo = std::max(a, 0.0), hi = std::min(b, sine_end(m));
    if (hi <= lo) return Vec2::Zero();
    const double w = 2.0 * M_PI * m.frequency;
    return m.amplitude * ((std::cos(w * lo) - std::cos(w * hi)) / w) / (t1 - t0);
  }
  return record_integral(m, a, b) / (t1 - t0);
}

}  // namespace dda
