// Joint sets as trace segments: a set of parallel joints of given dip and mean
// spacing, persistent or broken by rock bridges, with scatter of dip and spacing drawn from
// a seed, so that a cut is reproducible. Pure functions; no CGAL.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "cutting/cut_domain.hpp"
#include "kinematics/types.hpp"

namespace dda {

struct JointSetSpec {
  double dip = 0.0;                     // degrees from the +x axis, counter-clockwise
  double spacing = 1.0;                 // m, mean distance between successive traces (> 0)
  std::optional<double> trace_length;   // m; none: every trace runs across the domain
  double bridge = 0.0;                  // m, rock bridge between traces on one line
  double offset = 0.0;                  // m, the first line's distance from the origin along the normal
  double dip_scatter = 0.0;             // degrees, standard deviation of each line's dip
  double spacing_scatter = 0.0;         // m, standard deviation of each gap between lines
};

// The traces of one set over the box [lo, hi] (the domain's bounding box): lines at
// distances offset + k spacing (k of either sign, gaps scattered) along the set's normal
// (-sin dip, cos dip), each turned by its own dip scatter about its point nearest the box's
// centre, cut into traces of trace_length with bridges between them from a random phase.
// Gaps are kept at least 0.1 spacing. Draws come from a 64-bit Mersenne Twister seeded with
// `seed` through this file's own uniform and normal transforms (the standard library's
// distributions differ between implementations), so a seed gives the same traces anywhere.
// `bridges`, if given, receives the rock bridges: the pieces of each line between its traces
// (in the box, as the traces are), so that traces and bridges together cover every line.
// Asking for them draws nothing more: the traces are the same either way.
std::vector<JointSegment> joint_set_traces(const JointSetSpec& set, const Vec2& lo, const Vec2& hi,
                                           std::uint64_t seed,
                                           std::vector<JointSegment>* bridges = nullptr);

// Whether joints of direction `dip` (degrees from +x, as JointSetSpec::dip) daylight in the
// face from p to q of a counter-clockwise domain (the rock on the face's left): they dip
// out of the face, towards the side its outward normal faces, and less steeply than the
// face, so that they outcrop on it and a block above one can slide out along it (the
// kinematic condition of planar sliding; Hoek and Bray, ch. 7). A face must look sideways,
// up or level (a vertical cliff counts; an overhang, a floor or a flat top has no
// daylighting joint).
bool daylights_in_face(double dip, const Vec2& p, const Vec2& q);

}  // namespace dda
