#include "cutting/cut_domain.hpp"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <optional>
#include <vector>

namespace dda {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_2;
using Traits = CGAL::Arr_segment_traits_2<Kernel>;
using Segment = Traits::Curve_2;
using Arrangement = CGAL::Arrangement_2<Traits>;

Point exact(const Vec2& p) { return Point(p.x(), p.y()); }
Vec2 plain(const Point& p) { return Vec2(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

// The points of a boundary cycle, vertices between two collinear edges dropped.
template <class Circulator>
std::vector<Point> cycle_points(Circulator first) {
  std::vector<Point> all;
  Circulator c = first;
  do {
    all.push_back(c->source()->point());
  } while (++c != first);
  std::vector<Point> kept;
  const std::size_t n = all.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!CGAL::collinear(all[(i + n - 1) % n], all[i], all[(i + 1) % n])) kept.push_back(all[i]);
  }
  return kept;
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

}  // namespace

CutResult cut_domain(const Polygon& domain, const std::vector<JointSegment>& joints,
                     double min_block_area) {
  CGAL::Polygon_2<Kernel> boundary;
  for (const Vec2& p : domain) boundary.push_back(exact(p));
  std::vector<Segment> segments;
  segments.reserve(domain.size() + joints.size());
  for (std::size_t i = 0; i < domain.size(); ++i) {
    segments.emplace_back(exact(domain[i]), exact(domain[(i + 1) % domain.size()]));
  }
  for (const JointSegment& j : joints) {
    if (j.from != j.to) segments.emplace_back(exact(j.from), exact(j.to));
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

  // Slivers: one merge at a time (a merge changes the faces around it), smallest first.
  for (;;) {
    Arrangement::Halfedge_handle best_edge;
    double smallest = min_block_area;
    for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
      if (f->is_unbounded()) continue;
      CGAL::Polygon_2<Kernel> outline;
      for (const Point& p : cycle_points(f->outer_ccb())) outline.push_back(p);
      const double area = CGAL::to_double(outline.area());
      if (area >= smallest) continue;
      // Its longest edge with a block on the other side.
      Arrangement::Halfedge_handle longest;
      Kernel::FT longest_length = 0;
      auto c = f->outer_ccb();
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
      smallest = area;
      best_edge = longest;
    }
    if (best_edge == Arrangement::Halfedge_handle()) break;
    arr.remove_edge(best_edge);
    ++result.slivers_merged;
    result.dead_end_edges += remove_edges_while(arr, dead_end);
  }

  // A face with a hole: bridge the hole to the outer boundary by a segment from the hole's
  // lowest-leftmost vertex straight down to the first edge below it, then start again.
  for (bool bridged = true; bridged;) {
    bridged = false;
    for (auto f = arr.faces_begin(); f != arr.faces_end() && !bridged; ++f) {
      if (f->is_unbounded() || f->number_of_holes() == 0) continue;
      Point low = (*f->holes_begin())->source()->point();
      auto h = *f->holes_begin();
      auto c = h;
      do {
        if (c->source()->point() < low) low = c->source()->point();
      } while (++c != h);
      // The nearest intersection below `low` with an edge not on the hole.
      std::optional<Point> hit;
      for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
        const Kernel::Segment_2 s(e->source()->point(), e->target()->point());
        const Kernel::Ray_2 down(low, Kernel::Direction_2(0, -1));
        const auto x = CGAL::intersection(s, down);
        if (!x) continue;
        const Point* p = boost::get<Point>(&*x);  // CGAL 5.5: a boost::variant
        if (p == nullptr || *p == low) continue;
        if (!hit || CGAL::has_larger_distance_to_point(low, *hit, *p)) hit = *p;
      }
      if (!hit) continue;  // cannot happen inside a bounded face; leave it
      CGAL::insert(arr, Segment(low, *hit));
      ++result.holes_bridged;
      bridged = true;
    }
  }

  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->is_unbounded()) continue;
    Polygon block;
    for (const Point& p : cycle_points(f->outer_ccb())) block.push_back(plain(p));
    result.blocks.push_back(std::move(block));
  }
  return result;
}

}  // namespace dda
