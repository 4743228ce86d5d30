#include "solver/joint_water.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <initializer_list>

#include "contact/narrow_phase.hpp"
#include "solver/world.hpp"

namespace dda {

double polyline_height(const std::vector<Vec2>& p, double x) {
  assert(p.size() >= 2);
  if (x <= p.front().x()) return p.front().y();
  if (x >= p.back().x()) return p.back().y();
  const auto next = std::upper_bound(p.begin(), p.end(), x,
                                     [](double v, const Vec2& q) { return v < q.x(); });
  const Vec2& b = *next;
  const Vec2& a = *(next - 1);
  return a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x());
}

double phreatic_height(const WaterTable& water, double x) {
  const double full = polyline_height(water.phreatic_line, x);
  if (water.dry_line.empty()) return full;
  const double dry = polyline_height(water.dry_line, x);
  return dry + water.fill * (full - dry);
}

SegmentPressure segment_pressure(const WaterTable& water, const Vec2& a, const Vec2& b) {
  const double length = (b - a).norm();
  SegmentPressure out;
  out.centre = 0.5 * (a + b);
  if (length == 0.0) return out;
  // Along the segment (parameter s in [0, 1]) the head h(x) - y is linear between the
  // segment's crossings of the lines' vertices' x: split there, then clip each piece where
  // the head turns negative, and integrate the linear head exactly (force and moment).
  std::vector<double> cuts{0.0, 1.0};
  const double dx = b.x() - a.x();
  if (dx != 0.0) {
    for (const std::vector<Vec2>* line : {&water.phreatic_line, &water.dry_line}) {
      for (const Vec2& q : *line) {
        const double s = (q.x() - a.x()) / dx;
        if (s > 0.0 && s < 1.0) cuts.push_back(s);
      }
    }
  }
  std::sort(cuts.begin(), cuts.end());
  auto head = [&](double s) {
    const Vec2 p = a + s * (b - a);
    return phreatic_height(water, p.x()) - p.y();
  };
  double force = 0.0, moment = 0.0;  // moment: integral of p(s) s ds, in units of length
  auto add_piece = [&](double s0, double s1, double h0, double h1) {
    // Linear head h0 -> h1 over [s0, s1], both >= 0.
    const double w = s1 - s0;
    force += 0.5 * (h0 + h1) * w;
    moment += w * (h0 * (2.0 * s0 + s1) + h1 * (s0 + 2.0 * s1)) / 6.0;
  };
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double s0 = cuts[k], s1 = cuts[k + 1];
    const double h0 = head(s0), h1 = head(s1);
    if (h0 <= 0.0 && h1 <= 0.0) continue;
    if (h0 >= 0.0 && h1 >= 0.0) {
      add_piece(s0, s1, h0, h1);
    } else {
      const double sz = s0 + (s1 - s0) * h0 / (h0 - h1);  // where the head is zero
      if (h0 > 0.0) add_piece(s0, sz, h0, 0.0);
      else add_piece(sz, s1, 0.0, h1);
    }
  }
  out.force = water.unit_weight * force * length;
  if (force > 0.0) out.centre = a + (moment / force) * (b - a);
  return out;
}

namespace {

// One joint face between two blocks: the pair (force on `a` along +normal, on `b` against
// it), the face's line (normal, offset = normal . x) and the intervals of it that the
// contacts' shares cover, as coordinates along the tangent (-normal.y, normal.x).
struct Face {
  int a = -1, b = -1;
  Vec2 normal = Vec2::Zero();
  double offset = 0.0;
  std::vector<std::pair<double, double>> covered;
};

}  // namespace

std::vector<BlockForce> joint_water_forces(const WaterTable& water,
                                           const std::vector<const Polygon*>& polygons,
                                           const std::vector<Contact>& contacts,
                                           double face_tolerance) {
  // A joint face may be covered by contacts from both sides: once it opens, a vertex of
  // either block may project on the other's edge. The shares are therefore collected per
  // face (the same pair of blocks, parallel within the wedge tolerance, lines within
  // face_tolerance of each other), their union taken, and the pressure on it counted once.
  std::vector<Face> faces;
  for (const Contact& c : contacts) {
    if (c.length <= 0.0) continue;  // a point contact: no face, no water force
    const int a = std::min(c.key.vertex_block, c.key.edge_block);
    const int b = std::max(c.key.vertex_block, c.key.edge_block);
    const Vec2 n = c.key.vertex_block == a ? c.normal : Vec2(-c.normal);  // pushes a off b
    const Polygon& vp = *polygons[static_cast<std::size_t>(c.key.vertex_block)];
    const Vec2& p = vp[static_cast<std::size_t>(c.key.vertex)];
    // The same share as the contact's length (and its cohesion).
    const FaceShares shares = face_shares(vp, c.key.vertex, c.edge_start, c.edge_end);
    for (int k = 0; k < shares.count; ++k) {
      const Vec2& half = shares.halves[static_cast<std::size_t>(k)];
      const Vec2& start = shares.from[static_cast<std::size_t>(k)];
      Face* face = nullptr;
      for (Face& f : faces) {
        if (f.a == a && f.b == b && f.normal.dot(n) > std::cos(kWedgeTolerance) &&
            std::abs(f.normal.dot(p) - f.offset) <= face_tolerance) {
          face = &f;
          break;
        }
      }
      if (face == nullptr) {
        faces.push_back({a, b, n, n.dot(p), {}});
        face = &faces.back();
      }
      const Vec2 t(-face->normal.y(), face->normal.x());
      const double s0 = t.dot(start), s1 = t.dot(start + half);
      face->covered.emplace_back(std::min(s0, s1), std::max(s0, s1));
    }
  }
  std::vector<BlockForce> out;
  for (Face& f : faces) {
    std::sort(f.covered.begin(), f.covered.end());
    const Vec2 t(-f.normal.y(), f.normal.x());
    auto flush = [&](double lo, double hi) {
      const SegmentPressure p =
          segment_pressure(water, f.offset * f.normal + lo * t, f.offset * f.normal + hi * t);
      if (p.force <= 0.0) return;
      out.push_back({f.a, p.centre, p.force * f.normal});
      out.push_back({f.b, p.centre, -p.force * f.normal});
    };
    double lo = f.covered.front().first, hi = f.covered.front().second;
    for (const auto& [s0, s1] : f.covered) {
      if (s0 > hi) {
        flush(lo, hi);
        lo = s0;
      }
      hi = std::max(hi, s1);
    }
    flush(lo, hi);
  }
  return out;
}

std::vector<BlockForce> present_water_forces(const World& world) {
  if (!world.water) return {};
  std::vector<const Polygon*> polygons;
  for (const Block& b : world.blocks) polygons.push_back(&b.vertices);
  WaterTable water = *world.water;
  if (!world.stages.stages.empty()) {
    const double scene_g = world.stages.gravity.norm();
    water.unit_weight *= scene_g > 0.0 ? world.gravity.norm() / scene_g : 0.0;
  }
  return joint_water_forces(water, polygons, world.contacts, world.search_distance);
}

}  // namespace dda
