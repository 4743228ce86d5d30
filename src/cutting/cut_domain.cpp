#include "cutting/cut_domain.hpp"

#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <queue>
#include <utility>
#include <vector>

#include "kinematics/polygon.hpp"

namespace dda {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_2;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;

// Where segments overlap, the edge they make has the higher of their groups (the caller
// numbers its groups so that this is the one it means: see BlockAdjacency).
struct HigherGroup {
  int operator()(int a, int b) const { return std::max(a, b); }
};
// Every curve, and every edge split from it, carries its segment's group: the arrangement
// keeps the data through the sweep's splits and overlaps, so the insertion stays one sweep.
using Traits = CGAL::Arr_curve_data_traits_2<SegmentTraits, int, HigherGroup>;
using Segment = Traits::Curve_2;
using Arrangement = CGAL::Arrangement_2<Traits>;

constexpr int kNoGroup = -1;

Segment segment(const Point& a, const Point& b, int group) {
  return Segment(SegmentTraits::Curve_2(a, b), group);
}

Point exact(const Vec2& p) { return Point(p.x(), p.y()); }
// + 0.0 turns a rounded -0 into 0, which reads better in a scene. Exact: the rounding of an
// intersection point may need its exact value, so this is done once a vertex.
Vec2 plain(const Point& p) {
  return Vec2(CGAL::to_double(p.x()) + 0.0, CGAL::to_double(p.y()) + 0.0);
}

// Near `p`: the middle of the interval the lazy kernel keeps for each coordinate (a few
// units in the last place wide), without the exact value. For areas and lengths that only
// order slivers or weigh a pair's joints.
Vec2 approximate(const Point& p) {
  const auto a = p.approx();
  return Vec2(0.5 * (a.x().inf() + a.x().sup()), 0.5 * (a.y().inf() + a.y().sup()));
}

// The part of segment a-b (as parameters 0 <= t0 < t1 <= 1) that the cut needs: from a
// little before its first crossing of the domain's boundary to a little after its last,
// unless an end lies inside (then from that end). Whatever lies beyond is outside the
// domain and would be removed edge by edge after the sweep, each removal walking the
// outside's boundary: in a domain with a long thin part outside its bounding box (a 100 km
// strip with a notch), that removal took minutes and gigabytes. `margin` (m) keeps each
// crossing inside the piece inserted, so that the exact boundary still cuts it there.
// Parallel to an edge, or in doubt: the whole segment. Nothing of it near the domain: none.
std::optional<std::pair<double, double>> part_near_domain(const Polygon& domain, const Vec2& a,
                                                          const Vec2& b, double margin) {
  const Vec2 ab = b - a;
  const double length = ab.norm();
  if (!(length > 0.0)) return std::pair{0.0, 1.0};
  constexpr double kSlack = 1e-9;  // crossings at an edge's end count (through a corner)
  double first = 2.0, last = -1.0;
  for (std::size_t i = 0; i < domain.size(); ++i) {
    const Vec2& p = domain[i];
    const Vec2 pq = domain[(i + 1) % domain.size()] - p;
    const double denom = cross(ab, pq);
    if (std::abs(denom) <= 1e-12 * length * pq.norm()) {
      if (std::abs(cross(p - a, ab)) <= 1e-9 * length * (length + (p - a).norm())) {
        return std::pair{0.0, 1.0};  // along an edge's line: kept whole
      }
      continue;
    }
    const double t = cross(p - a, pq) / denom, u = cross(p - a, ab) / denom;
    if (u < -kSlack || u > 1.0 + kSlack || t < -kSlack || t > 1.0 + kSlack) continue;
    first = std::min(first, t);
    last = std::max(last, t);
  }
  if (first > last) {  // no crossing: wholly inside, or wholly outside
    if (contains_point(domain, 0.5 * (a + b))) return std::pair{0.0, 1.0};
    return std::nullopt;
  }
  const double m = margin / length;
  const double t0 = contains_point(domain, a) ? 0.0 : std::max(0.0, first - m);
  const double t1 = contains_point(domain, b) ? 1.0 : std::min(1.0, last + m);
  return std::pair{t0, t1};
}

// The pieces of joint j that do not run along an edge of the domain. A joint on the line of a
// domain edge (both of the edge's ends within `tolerance` m of the joint's line) adds nothing
// there, where the boundary already is a free face, but rounded a hair off the edge (a trace
// of dip 45 through the corner of a 45-degree face: cos and sin of pi/4 differ in the last
// bit) it cut a sliver of no thickness between itself and the face, which merged into its
// neighbour as a polygon crossing itself. So the stretch along the edge is left out, and
// the joint's pieces beyond it end exactly at the edge's corners.
std::vector<JointSegment> off_domain_edges(const Polygon& domain, const JointSegment& j,
                                           double tolerance) {
  std::vector<JointSegment> pieces{j}, done;
  while (!pieces.empty()) {
    const JointSegment piece = pieces.back();
    pieces.pop_back();
    const Vec2 ab = piece.to - piece.from;
    const double length = ab.norm();
    bool split = false;
    for (std::size_t i = 0; i < domain.size() && length > 0.0 && !split; ++i) {
      const Vec2& p = domain[i];
      const Vec2& q = domain[(i + 1) % domain.size()];
      const auto off_line = [&](const Vec2& x) { return std::abs(cross(ab, x - piece.from)) / length; };
      if (off_line(p) > tolerance || off_line(q) > tolerance) continue;
      const double tp = (p - piece.from).dot(ab) / (length * length);
      const double tq = (q - piece.from).dot(ab) / (length * length);
      const double s0 = std::max(0.0, std::min(tp, tq)), s1 = std::min(1.0, std::max(tp, tq));
      if (!((s1 - s0) * length > tolerance)) continue;  // touches the edge's line only
      const Vec2& first = tp < tq ? p : q;   // the corner at s0
      const Vec2& second = tp < tq ? q : p;  // the corner at s1
      if (s0 * length > tolerance) pieces.push_back({piece.from, first, piece.group});
      if ((1.0 - s1) * length > tolerance) pieces.push_back({second, piece.to, piece.group});
      split = true;
    }
    if (!split) done.push_back(piece);
  }
  return done;
}

// The joints with exact duplicates left out (the same two ends, in either order), each kept
// where it first appears with the highest group of its copies, as the arrangement gives an
// edge that overlapping segments make. Two sets of one dip, spacing and offset, or a joint
// listed twice, draw the same segments, and CGAL's sweep meets k copies of a curve pair by
// pair: a model whose two sets were listed 1500 times each cut for minutes.
std::vector<JointSegment> distinct_segments(const std::vector<JointSegment>& joints) {
  const auto key = [&](std::size_t i) {
    const JointSegment& j = joints[i];
    const bool forward = std::pair(j.from.x(), j.from.y()) <= std::pair(j.to.x(), j.to.y());
    const Vec2& a = forward ? j.from : j.to;
    const Vec2& b = forward ? j.to : j.from;
    return std::array<double, 4>{a.x(), a.y(), b.x(), b.y()};
  };
  std::vector<std::size_t> order(joints.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::vector<int> group(joints.size());
  std::vector<bool> keep(joints.size(), true);
  for (std::size_t i = 0; i < joints.size(); ++i) group[i] = joints[i].group;
  // In each run of equal keys the stable sort puts the earliest in the list first: kept.
  std::size_t head = order.empty() ? 0 : order[0];
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t i = order[k];
    if (key(i) != key(head)) {
      head = i;
      continue;
    }
    keep[i] = false;
    group[head] = std::max(group[head], joints[i].group);
  }
  std::vector<JointSegment> out;
  out.reserve(joints.size());
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (keep[i]) out.push_back({joints[i].from, joints[i].to, group[i]});
  }
  return out;
}

// The point at parameter t of segment a-b, exactly on its line (so that clipping a joint
// moves no block corner by a rounding).
Point along(const Point& a, const Point& b, double t) {
  if (t == 0.0) return a;
  if (t == 1.0) return b;
  return a + Kernel::FT(t) * (b - a);
}

// A corner of a boundary cycle (a vertex between two edges that are not collinear, as
// cycle_corners decides) and the lengths, by joint group, of the halfedges from it to the next corner: one
// edge of the block, which may be several halfedges where other traces end on it.
struct Corner {
  Arrangement::Vertex_const_handle vertex;
  std::map<int, double> lengths;  // group -> length of the span's halfedges
};

// The group with the longest length (the lower group on a tie), -1 if none: a pair's
// (adjacency).
int longest_group(const std::map<int, double>& lengths) {
  int group = kNoGroup;
  double longest = -1.0;
  for (const auto& [g, length] : lengths) {  // groups in increasing order
    if (length > longest) {
      longest = length;
      group = g;
    }
  }
  return group;
}

// The corners of a boundary cycle in its order, from the first corner at or after `first`.
template <class Circulator>
std::vector<Corner> cycle_corners(Circulator first) {
  std::vector<Circulator> all;
  Circulator c = first;
  do {
    all.push_back(c);
  } while (++c != first);
  const std::size_t n = all.size();
  // A corner where the boundary turns. Where it goes straight on from one joint group to
  // another (a trace and the rock bridge after it) the edge goes on: its parts' lengths by
  // group say what it is made of (a straight vertex between the two would be a corner that
  // two blocks share, whose contact comes back at either edge as the blocks move). A trace's
  // and its bridge's ends are rounded onto their line in doubles, not exactly: a vertex where
  // only the two meet (degree 2) goes when they are straight to 1e-9 (the boundary moves by
  // that share of their length at most, the same for the blocks on both sides).
  const auto kept = [&](std::size_t i) {
    const Point& p = all[(i + n - 1) % n]->source()->point();
    const Point& q = all[i]->source()->point();
    const Point& r = all[i]->target()->point();
    if (CGAL::collinear(p, q, r)) return false;
    if (all[i]->source()->degree() != 2) return true;
    const Vec2 a = approximate(q) - approximate(p), b = approximate(r) - approximate(q);
    return std::abs(a.x() * b.y() - a.y() * b.x()) > 1e-9 * a.norm() * b.norm() || a.dot(b) <= 0.0;
  };
  std::size_t start = 0;
  while (start < n && !kept(start)) ++start;
  std::vector<Corner> corners;
  if (start == n) return corners;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (start + k) % n;
    if (kept(i)) corners.push_back({all[i]->source(), {}});
    const double length =
        (approximate(all[i]->target()->point()) - approximate(all[i]->source()->point())).norm();
    corners.back().lengths[all[i]->curve().data()] += length;
  }
  return corners;
}

// The nearest point where the ray from `from` in direction `d` meets an edge, other than
// `from` itself. Edges along the ray are met at their ends (by the edges there).
std::optional<Point> first_hit(const Arrangement& arr, const Point& from,
                               const Kernel::Direction_2& d) {
  const Kernel::Ray_2 ray(from, d);
  std::optional<Point> hit;
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    const Kernel::Segment_2 s(e->source()->point(), e->target()->point());
    const auto x = CGAL::intersection(s, ray);
    if (!x) continue;
    const Point* p = boost::get<Point>(&*x);  // CGAL 5.5: a boost::variant
    if (p == nullptr || *p == from) continue;
    if (!hit || CGAL::has_larger_distance_to_point(from, *hit, *p)) hit = *p;
  }
  return hit;
}

// Every vertex's point in doubles, vertices joined by edges no longer than `tol` gathered
// into one point: a corner of the domain if the group has one, else its first vertex's.
std::map<const Arrangement::Vertex*, Vec2> snapped_corners(const Arrangement& arr,
                                                          const Polygon& domain, double tol) {
  std::map<const Arrangement::Vertex*, int> index;
  std::vector<const Arrangement::Vertex*> vertices;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    index[&*v] = static_cast<int>(vertices.size());
    vertices.push_back(&*v);
  }
  std::vector<Vec2> rounded;
  rounded.reserve(vertices.size());
  for (const Arrangement::Vertex* v : vertices) rounded.push_back(plain(v->point()));
  std::vector<int> parent(vertices.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  const auto root = [&parent](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    const int i = index.at(&*e->source()), j = index.at(&*e->target());
    const Vec2 d = rounded[static_cast<std::size_t>(i)] - rounded[static_cast<std::size_t>(j)];
    if (d.norm() > tol) continue;
    const int a = root(i), b = root(j);
    parent[std::max(a, b)] = std::min(a, b);
  }
  const auto is_domain_corner = [&domain](const Vec2& p) {
    return std::find(domain.begin(), domain.end(), p) != domain.end();
  };
  std::vector<std::optional<Vec2>> group_point(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2& p = rounded[i];
    std::optional<Vec2>& g = group_point[static_cast<std::size_t>(root(static_cast<int>(i)))];
    if (!g || (is_domain_corner(p) && !is_domain_corner(*g))) g = p;
  }
  std::map<const Arrangement::Vertex*, Vec2> out;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    out[vertices[i]] = *group_point[static_cast<std::size_t>(root(static_cast<int>(i)))];
  }
  return out;
}

// Removes every edge for which `doomed` holds, until none does (a removal can make another
// edge doomed: a dead end's next piece).
template <class Doomed>
int remove_edges_while(Arrangement& arr, Doomed doomed) {
  int removed = 0;
  for (;;) {
    std::vector<Arrangement::Halfedge_handle> edges;
    for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
      if (doomed(e)) edges.push_back(e);
    }
    if (edges.empty()) return removed;
    for (auto e : edges) arr.remove_edge(e);
    removed += static_cast<int>(edges.size());
  }
}

// Removes the dead ends of face `f` (edges with `f` on both sides), repeatedly: those a
// merge into `f` leaves, which lie on its boundary only (a whole-arrangement scan after each
// of hundreds of merges would cost more than the cut).
int remove_dead_ends_of(Arrangement& arr, Arrangement::Face_handle f) {
  int removed = 0;
  for (;;) {
    std::vector<Arrangement::Halfedge_handle> dead;
    const auto scan = [&](Arrangement::Ccb_halfedge_circulator first) {
      auto c = first;
      do {
        // Both halves of a dead end lie on f's boundary: keep one.
        if (c->twin()->face() == f &&
            std::less<const Arrangement::Halfedge*>{}(&*c, &*c->twin())) {
          dead.push_back(c);
        }
      } while (++c != first);
    };
    scan(f->outer_ccb());
    for (auto h = f->holes_begin(); h != f->holes_end(); ++h) scan(*h);
    if (dead.empty()) return removed;
    for (auto e : dead) arr.remove_edge(e);
    removed += static_cast<int>(dead.size());
  }
}

// Slivers, smallest first, each merged into the neighbour across its longest edge (the
// edge removed, then any dead end that leaves). Faces wait in a queue by area; a merge
// queues the merged face afresh, and an entry whose face has been merged away or has
// changed its area since is skipped. Merges only delete faces, never make one, so a face's
// address names it throughout. Areas in doubles: enough to order faces and to compare them
// with `min_block_area`.
void merge_slivers(Arrangement& arr, double min_block_area, CutResult& result) {
  const auto outer_area = [](Arrangement::Face_handle f) {
    double twice = 0.0;
    auto c = f->outer_ccb();
    const auto first = c;
    do {
      const Vec2 p = approximate(c->source()->point()), q = approximate(c->target()->point());
      twice += p.x() * q.y() - p.y() * q.x();
    } while (++c != first);
    return 0.5 * twice;
  };
  struct Entry {
    double area;
    std::size_t order;  // ties in queueing order, so that the cut is the same every run
    Arrangement::Face_handle face;
    bool operator>(const Entry& o) const {
      return area != o.area ? area > o.area : order > o.order;
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  std::map<const Arrangement::Face*, double> area_of;  // faces alive, by area
  std::size_t order = 0;
  const auto enqueue = [&](Arrangement::Face_handle f) {
    const double a = outer_area(f);
    area_of[&*f] = a;
    if (a < min_block_area) queue.push({a, order++, f});
  };
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (!f->is_unbounded()) enqueue(f);
  }
  while (!queue.empty()) {
    const Entry top = queue.top();
    queue.pop();
    const auto alive = area_of.find(&*top.face);
    if (alive == area_of.end() || alive->second != top.area) continue;
    // Its longest edge with a block on the other side.
    Arrangement::Halfedge_handle longest;
    Kernel::FT longest_length = 0;
    auto c = top.face->outer_ccb();
    const auto first = c;
    do {
      if (!c->twin()->face()->is_unbounded()) {
        const Kernel::FT l = CGAL::squared_distance(c->source()->point(), c->target()->point());
        if (l > longest_length) {
          longest_length = l;
          longest = c;
        }
      }
    } while (++c != first);
    if (longest_length == 0) continue;  // alone against the boundary: kept
    area_of.erase(&*top.face);
    area_of.erase(&*longest->twin()->face());
    const Arrangement::Face_handle merged = arr.remove_edge(longest);
    ++result.slivers_merged;
    result.dead_end_edges += remove_dead_ends_of(arr, merged);
    enqueue(merged);
  }
}

// The pairs of blocks on the two sides of each edge between two bounded faces, with the
// length each group contributes; per pair the group of the longest total (the lower on a tie).
std::vector<BlockAdjacency> adjacency(const Arrangement& arr,
                                      const std::map<const Arrangement::Face*, int>& block_of) {
  std::map<std::pair<int, int>, std::map<int, double>> lengths;  // pair -> group -> length
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    // Faces left out (the unbounded one, collapsed ones) have no block.
    const auto fi = block_of.find(&*e->face()), fj = block_of.find(&*e->twin()->face());
    if (fi == block_of.end() || fj == block_of.end()) continue;
    const int i = fi->second, j = fj->second;
    if (i == j) continue;  // cannot happen once dead ends are gone; harmless if it did
    const double length =
        (approximate(e->target()->point()) - approximate(e->source()->point())).norm();
    lengths[std::minmax(i, j)][e->curve().data()] += length;
  }
  std::vector<BlockAdjacency> pairs;
  pairs.reserve(lengths.size());
  for (const auto& [pair, by_group] : lengths) {
    BlockAdjacency adjacent{pair.first, pair.second, longest_group(by_group), 0.0};
    for (const auto& [group, length] : by_group) adjacent.shared_length += length;
    pairs.push_back(adjacent);
  }
  return pairs;
}

}  // namespace

CutResult cut_domain(const Polygon& domain, const std::vector<JointSegment>& joints,
                     double min_block_area) {
  CGAL::Polygon_2<Kernel> boundary;
  for (const Vec2& p : domain) boundary.push_back(exact(p));
  std::vector<Segment> segments;
  segments.reserve(domain.size() + joints.size());
  for (std::size_t i = 0; i < domain.size(); ++i) {
    const Vec2& next = domain[(i + 1) % domain.size()];
    segments.push_back(segment(exact(domain[i]), exact(next), kNoGroup));
  }
  Vec2 lo = domain.front(), hi = lo;
  for (const Vec2& p : domain) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double margin = 1e-6 * (hi - lo).norm() + 1e-9;
  // Along a domain edge: within the rounding the cut allows elsewhere (labels, fixed blocks).
  const double along_edge = 1e-9 * (hi - lo).norm();
  for (const JointSegment& whole : distinct_segments(joints)) {
    for (const JointSegment& j : off_domain_edges(domain, whole, along_edge)) {
      if (j.from == j.to) continue;
      const auto part = part_near_domain(domain, j.from, j.to, margin);
      if (!part) continue;
      const Point a = exact(j.from), b = exact(j.to);
      segments.push_back(segment(along(a, b, part->first), along(a, b, part->second), j.group));
    }
  }
  Arrangement arr;
  CGAL::insert(arr, segments.begin(), segments.end());  // one sweep

  // Every edge now lies inside the domain, on its boundary, or outside: the boundary splits
  // the traces where they cross it. The outside ones go (their midpoints decide).
  remove_edges_while(arr, [&boundary](Arrangement::Edge_iterator e) {
    const Point m = CGAL::midpoint(e->source()->point(), e->target()->point());
    return boundary.bounded_side(m) == CGAL::ON_UNBOUNDED_SIDE;
  });
  CutResult result;
  const auto dead_end = [](Arrangement::Edge_iterator e) { return e->face() == e->twin()->face(); };
  result.dead_end_edges = remove_edges_while(arr, dead_end);

  merge_slivers(arr, min_block_area, result);

  // A face with a hole: two bridges from the hole to what surrounds it, one straight down
  // from its lowest vertex of least x, one straight up from its highest vertex of greatest x
  // (nothing of the hole lies below the one or above the other), then start again. One
  // bridge alone would leave a slit, an edge with the same block on both sides, which no
  // simple polygon has; two split the face into simple blocks (or reach another hole, which
  // gets its own two).
  for (bool bridged = true; bridged;) {
    bridged = false;
    for (auto f = arr.faces_begin(); f != arr.faces_end() && !bridged; ++f) {
      if (f->is_unbounded() || f->number_of_holes() == 0) continue;
      const auto h = *f->holes_begin();
      Point low = h->source()->point(), high = low;
      auto c = h;
      do {
        low = std::min(low, c->source()->point());
        high = std::max(high, c->source()->point());
      } while (++c != h);
      const std::optional<Point> below = first_hit(arr, low, Kernel::Direction_2(0, -1));
      const std::optional<Point> above = first_hit(arr, high, Kernel::Direction_2(0, 1));
      if (!below || !above) continue;  // cannot happen inside a bounded face; leave it
      const std::vector<Segment> bridges{segment(low, *below, kNoGroup),
                                         segment(high, *above, kNoGroup)};
      CGAL::insert(arr, bridges.begin(), bridges.end());
      ++result.holes_bridged;
      bridged = true;
    }
  }

  // Corners to doubles, each once. Vertices joined by an edge shorter than 1e-12 of the
  // domain's diagonal (a trace through a corner of the domain, up to its rounding; traces
  // crossing all but at one point) become one point, so that no block has an edge the scene
  // reader would take for a repeated vertex (its tolerance: 1e-12 of the block's diagonal,
  // never more than the domain's). A point moves by about that much, far inside the
  // touching tolerance between blocks (1e-9 of a block's size).
  const Box box = bounding_box(domain);
  const std::map<const Arrangement::Vertex*, Vec2> corner =
      snapped_corners(arr, domain, 1e-12 * (box.max - box.min).norm());
  std::map<const Arrangement::Face*, int> block_of;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->is_unbounded()) continue;
    Polygon block;
    std::vector<std::map<int, double>> edge_lengths;  // per edge of `block`: group -> length
    for (const Corner& k : cycle_corners(f->outer_ccb())) {
      const Vec2& p = corner.at(&*k.vertex);
      if (block.empty() || block.back() != p) {
        block.push_back(p);
        edge_lengths.emplace_back();
      }
      // A corner rounded onto the one before it adds its edge's span to that one's.
      for (const auto& [g, length] : k.lengths) edge_lengths.back()[g] += length;
    }
    while (block.size() > 1 && block.back() == block.front()) {
      block.pop_back();
      for (const auto& [g, length] : edge_lengths.back()) edge_lengths[edge_lengths.size() - 2][g] += length;
      edge_lengths.pop_back();
    }
    // A face that is no more than a line once rounded (narrower than 1e-11 of its size, so
    // that the scene reader, at 1e-12, would find no area) is left out: nothing is lost.
    const Box b = bounding_box(block);
    const double size = (b.max - b.min).norm();
    if (block.size() < 3 || std::abs(signed_area(block)) <= 1e-11 * size * size) {
      ++result.collapsed_faces;
      continue;
    }
    block_of[&*f] = static_cast<int>(result.blocks.size());
    result.blocks.push_back(std::move(block));
    std::vector<std::vector<std::pair<int, double>>> parts;
    for (const auto& lengths : edge_lengths) parts.emplace_back(lengths.begin(), lengths.end());
    result.edge_parts.push_back(std::move(parts));
  }
  result.adjacency = adjacency(arr, block_of);
  return result;
}

}  // namespace dda
