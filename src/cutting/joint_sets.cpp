#include "cutting/joint_sets.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <random>

namespace dda {
namespace {

// Uniform in [0, 1) from the engine's 53 high bits (the same on every platform).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Standard normal by Box-Muller (one of the pair used).
double normal(std::mt19937_64& rng) {
  const double u1 = 1.0 - uniform(rng);  // (0, 1]: log is finite
  const double u2 = uniform(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

// The parameter range [t0, t1] of the line through `p` along unit `d` inside the box
// widened by `margin` on every side (Liang and Barsky's slab clipping); empty (t0 > t1) when
// the line misses it.
std::pair<double, double> clip_to_box(const Vec2& p, const Vec2& d, const Vec2& lo, const Vec2& hi,
                                      double margin) {
  double t0 = -std::numeric_limits<double>::infinity(), t1 = -t0;
  for (int k = 0; k < 2; ++k) {
    const double a = lo[k] - margin - p[k], b = hi[k] + margin - p[k];
    if (d[k] == 0.0) {
      if (a > 0.0 || b < 0.0) return {1.0, 0.0};
      continue;
    }
    const double ta = a / d[k], tb = b / d[k];
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  }
  return {t0, t1};
}

// The segments of the line through `p` along unit `d` inside the box (with a small margin
// beyond it, so that a trace crossing the boundary is cut by it, not ending on it), cut into traces
// with bridges, or whole. Clipped to the box itself, not to its projection on the line: in a
// tall narrow domain the projection made every line hundreds of metres long and every pair of
// lines cross outside the domain (a 20 m x 10 km strip: 57 s and 6.8 GB for 13 000 blocks).
void add_line(const JointSetSpec& set, const Vec2& p, const Vec2& d, const Vec2& lo,
              const Vec2& hi, std::mt19937_64& rng, std::vector<JointSegment>& out,
              std::vector<JointSegment>* bridges) {
  // The margin is a share of the box's smaller side: beyond the domain each line is a stub
  // that the cut removes, and in a strip 10 km long and 10 m high a share of the diagonal
  // (100 m) made a mesh of crossings outside it whose removal took most of the cut.
  const Vec2 size = hi - lo;
  const double margin = 0.01 * std::min(size.x(), size.y()) + 1e-9;
  const auto [c0, c1] = clip_to_box(p, d, lo, hi, margin);
  if (!set.trace_length) {
    if (c1 > c0) out.push_back({p + c0 * d, p + c1 * d});
    return;
  }
  // The traces' phase runs from the box's projection on the line (as it always did, so that
  // a model's random traces stay where they were); only their pieces in the box are kept.
  double t0 = 0.0, t1 = 0.0;
  bool first = true;
  for (const Vec2& c : {lo, hi, Vec2(lo.x(), hi.y()), Vec2(hi.x(), lo.y())}) {
    const double t = d.dot(c - p);
    t0 = first ? t : std::min(t0, t);
    t1 = first ? t : std::max(t1, t);
    first = false;
  }
  const double phase_margin = 0.01 * size.norm() + 1e-9;
  t0 -= phase_margin;
  t1 += phase_margin;
  const double length = *set.trace_length;
  const double period = length + set.bridge;
  double t = t0 - uniform(rng) * period;  // a random phase per line
  for (; t < t1; t += period) {
    const double a = std::max({t, t0, c0}), b = std::min({t + length, t1, c1});
    if (b > a) out.push_back({p + a * d, p + b * d});
    if (bridges != nullptr) {  // the bridge after this trace, to the next one's start
      const double ba = std::max({t + length, t0, c0}), bb = std::min({t + period, t1, c1});
      if (bb > ba) bridges->push_back({p + ba * d, p + bb * d});
    }
  }
  // The first trace starts at or before t0, and the last period ends at or after t1: with
  // the bridges, the pieces cover the whole line in the box.
}

}  // namespace

std::vector<JointSegment> joint_set_traces(const JointSetSpec& set, const Vec2& lo, const Vec2& hi,
                                           std::uint64_t seed, std::vector<JointSegment>* bridges) {
  std::mt19937_64 rng(seed);
  const double dip = set.dip * M_PI / 180.0;
  const Vec2 direction(std::cos(dip), std::sin(dip));
  const Vec2 n(-direction.y(), direction.x());
  // The box's extent along the normal: lines from below it to above it.
  double s_lo = 0.0, s_hi = 0.0;
  bool first = true;
  for (const Vec2& c : {lo, hi, Vec2(lo.x(), hi.y()), Vec2(hi.x(), lo.y())}) {
    const double s = n.dot(c);
    s_lo = first ? s : std::min(s_lo, s);
    s_hi = first ? s : std::max(s_hi, s);
    first = false;
  }
  const Vec2 centre = 0.5 * (lo + hi);
  std::vector<JointSegment> out;
  // The first line at or below s_lo on the grid offset + k spacing, then gap after gap.
  double s = set.offset + std::floor((s_lo - set.offset) / set.spacing) * set.spacing;
  while (s <= s_hi) {
    // The line's point nearest the box's centre, and its own dip.
    const Vec2 p = centre + (s - n.dot(centre)) * n;
    const double own = dip + set.dip_scatter * M_PI / 180.0 * normal(rng);
    add_line(set, p, Vec2(std::cos(own), std::sin(own)), lo, hi, rng, out, bridges);
    const double gap = set.spacing + set.spacing_scatter * normal(rng);
    s += std::max(gap, 0.1 * set.spacing);
  }
  return out;
}

bool daylights_in_face(double dip, const Vec2& p, const Vec2& q) {
  const Vec2 edge = q - p;
  const double length = edge.norm();
  if (!(length > 0.0)) return false;
  const Vec2 outward(edge.y() / length, -edge.x() / length);  // the rock is on the left
  constexpr double kFlat = 1e-9;
  if (outward.y() < -kFlat || std::abs(outward.x()) <= kFlat) return false;
  const double face_dip = std::atan2(std::abs(edge.y()), std::abs(edge.x()));
  // The joint's line as an angle in [0, pi): rising to +x below pi/2 (it dips towards -x),
  // to -x above (it dips towards +x).
  double theta = std::fmod(dip * M_PI / 180.0, M_PI);
  if (theta < 0.0) theta += M_PI;
  const double joint_dip = theta <= 0.5 * M_PI ? theta : M_PI - theta;
  if (!(joint_dip > kFlat) || joint_dip >= 0.5 * M_PI - kFlat) return false;  // flat or vertical
  const double dips_towards = theta < 0.5 * M_PI ? -1.0 : 1.0;
  return dips_towards * outward.x() > 0.0 && joint_dip < face_dip;
}

}  // namespace dda
