// Joint sets as traces (cutting/joint_sets): orientation, spacing and persistence
// of the traces against their inputs, exactly without scatter and statistically with it,
// reproducibly from a seed; and a slope cut by two sets.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <vector>

#include "cutting/cut_domain.hpp"
#include "cutting/joint_sets.hpp"
#include "kinematics/polygon.hpp"

using namespace dda;

namespace {

// Where the trace's line crosses the normal line through `centre`, as a distance along the
// set's normal `n` (joint_set_traces turns each line about exactly that point).
double line_distance(const JointSegment& t, const Vec2& centre, const Vec2& n) {
  const Vec2 d = (t.to - t.from).normalized();
  return n.dot(centre) + cross(t.from - centre, d) / cross(n, d);
}

struct Stats {
  double mean = 0.0, sd = 0.0;
};
Stats stats(const std::vector<double>& xs) {
  Stats s;
  for (double x : xs) s.mean += x;
  s.mean /= static_cast<double>(xs.size());
  for (double x : xs) s.sd += (x - s.mean) * (x - s.mean);
  s.sd = std::sqrt(s.sd / static_cast<double>(xs.size() - 1));
  return s;
}

}  // namespace

TEST_CASE("a persistent set without scatter has its dip and spacing exactly", "[cutting]") {
  JointSetSpec set;
  set.dip = 30.0;
  set.spacing = 2.0;
  set.offset = 0.5;
  const Vec2 lo(0, 0), hi(20, 10);
  const std::vector<JointSegment> traces = joint_set_traces(set, lo, hi, 1);
  const Vec2 d(std::cos(M_PI / 6), std::sin(M_PI / 6)), n(-d.y(), d.x());
  // Lines cover the box's extent along n: n.(20, 0) = -10 to n.(0, 10) = 8.66.
  REQUIRE(traces.size() >= 9);
  std::vector<double> s;
  for (const JointSegment& t : traces) {
    CHECK(std::abs(cross((t.to - t.from).normalized(), d)) < 1e-12);
    s.push_back(n.dot(t.from));
    // Each line runs past the box: both ends outside it.
    CHECK_FALSE(contains_point({lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}, t.from));
    CHECK_FALSE(contains_point({lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}, t.to));
  }
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double steps = (s[k] - 0.5) / 2.0;
    CHECK(std::abs(steps - std::round(steps)) < 1e-9);  // on the grid offset + k spacing
    if (k > 0) CHECK(s[k] - s[k - 1] == Approx(2.0).epsilon(1e-9));
  }
}

TEST_CASE("a line is clipped to the box, not to the box's projection on it", "[cutting]") {
  // In a 20 m x 1000 m box a 25 degree line crosses 20 / cos 25 = 22.1 m of it. Clipped to
  // the box's projection on the line (20 cos 25 + 1000 sin 25 = 441 m) every line crossed
  // every other outside the domain: a 20 m x 10 km strip took 57 s and 6.8 GB to cut into
  // 13 000 blocks (the fuzzer's find). Expected length: the
  // chord of the box widened by the margin, 0.01 x its smaller side (+1e-9 m) on each side:
  // (20 + 2 m) / cos 25, m = 0.2; checked to round-off of the clipping (1e-9 m).
  const Vec2 lo(0, 0), hi(20, 1000);
  const double margin = 0.01 * 20.0 + 1e-9;
  const double chord = (20.0 + 2.0 * margin) / std::cos(25.0 * M_PI / 180.0);
  for (const bool traces_of_finite_length : {false, true}) {
    JointSetSpec set;
    set.dip = 25.0;
    set.spacing = 2.0;
    if (traces_of_finite_length) {
      set.trace_length = 1000.0;  // longer than any chord: every piece is clipped by the box
      set.bridge = 0.5;
    }
    const std::vector<JointSegment> traces = joint_set_traces(set, lo, hi, 3);
    REQUIRE(traces.size() > 400);  // about (20 sin 25 + 1000 cos 25) / 2 = 457 lines
    int full = 0;
    for (const JointSegment& t : traces) {
      const double length = (t.to - t.from).norm();
      CHECK(length <= chord + 1e-9);
      if (length > chord - 1e-9) ++full;
      for (const Vec2& end : {t.from, t.to}) {  // both ends on the widened box
        CHECK(end.x() >= lo.x() - margin - 1e-9);
        CHECK(end.x() <= hi.x() + margin + 1e-9);
      }
    }
    // Lines through the box's long sides (not its corners' triangles) run the full chord.
    CHECK(full > 400);
  }
}

TEST_CASE("scattered dip and spacing match their inputs statistically", "[cutting]") {
  // dip 60 +- 4 degrees, spacing 1 +- 0.2 m over a 200 m box: about 270 lines. The sample
  // means are within 4 standard errors of the inputs (sd / sqrt(N): 0.25 degrees, 0.012 m)
  // and the sample standard deviations within 15 % (their relative standard error is
  // 1 / sqrt(2 N), about 4 %: 15 % is 3.5 of them). The seed fixes the draw; these bounds
  // say the draw is of the distribution asked for, whatever the seed.
  JointSetSpec set;
  set.dip = 60.0;
  set.spacing = 1.0;
  set.dip_scatter = 4.0;
  set.spacing_scatter = 0.2;
  const Vec2 lo(0, 0), hi(200, 200), centre(100, 100);
  const std::vector<JointSegment> traces = joint_set_traces(set, lo, hi, 42);
  REQUIRE(traces.size() > 200);
  const Vec2 n(-std::sin(M_PI / 3), std::cos(M_PI / 3));
  std::vector<double> dips, gaps;
  double last = 0.0;
  for (std::size_t k = 0; k < traces.size(); ++k) {
    const Vec2 d = traces[k].to - traces[k].from;
    dips.push_back(std::atan2(d.y(), d.x()) * 180.0 / M_PI);
    const double s = line_distance(traces[k], centre, n);
    if (k > 0) gaps.push_back(s - last);
    last = s;
  }
  const double count = static_cast<double>(traces.size());
  const Stats dip = stats(dips), gap = stats(gaps);
  CHECK(std::abs(dip.mean - 60.0) < 4.0 * 4.0 / std::sqrt(count));
  CHECK(std::abs(gap.mean - 1.0) < 4.0 * 0.2 / std::sqrt(count));
  CHECK(dip.sd == Approx(4.0).epsilon(0.15));
  CHECK(gap.sd == Approx(0.2).epsilon(0.15));

  // The same seed gives the same traces; another seed others.
  const std::vector<JointSegment> again = joint_set_traces(set, lo, hi, 42);
  REQUIRE(again.size() == traces.size());
  for (std::size_t k = 0; k < traces.size(); ++k) {
    CHECK(again[k].from == traces[k].from);
    CHECK(again[k].to == traces[k].to);
  }
  const std::vector<JointSegment> other = joint_set_traces(set, lo, hi, 43);
  CHECK((other.size() != traces.size() || other[0].from != traces[0].from));
}

// Horizontal lines 1 m apart, traces of 5 m with 2 m rock bridges between them.
JointSetSpec broken_horizontal_set() {
  JointSetSpec set;
  set.dip = 0.0;
  set.spacing = 1.0;
  set.trace_length = 5.0;
  set.bridge = 2.0;
  return set;
}

TEST_CASE("traces and rock bridges alternate along each line", "[cutting]") {
  // Horizontal lines 1 m apart over a 100 m x 20 m box, traces of 5 m with 2 m bridges from
  // a random phase: every trace at most 5 m, consecutive traces on a line 2 m apart, and
  // the traces cover 5/7 of the lines' length inside the box, within 0.02 (the two partial
  // periods at the ends of each line shift it by at most 7/100 per line, averaging out over
  // 21 lines of independent phases).
  const JointSetSpec set = broken_horizontal_set();
  const std::vector<JointSegment> traces = joint_set_traces(set, {0, 0}, {100, 20}, 7);
  double inside = 0.0;
  int lines = 0;
  for (std::size_t k = 0; k < traces.size(); ++k) {
    const JointSegment& t = traces[k];
    CHECK(t.from.y() == t.to.y());
    CHECK((t.to - t.from).norm() <= 5.0 + 1e-9);
    const double a = std::clamp(t.from.x(), 0.0, 100.0), b = std::clamp(t.to.x(), 0.0, 100.0);
    if (t.from.y() >= 0.0 && t.from.y() <= 20.0) inside += b - a;
    if (k == 0 || traces[k - 1].from.y() != t.from.y()) {
      if (t.from.y() >= 0.0 && t.from.y() <= 20.0) ++lines;
    } else {
      CHECK(t.from.x() - traces[k - 1].to.x() == Approx(2.0).epsilon(1e-9));
    }
  }
  REQUIRE(lines == 21);
  CHECK(inside / (100.0 * lines) == Approx(5.0 / 7.0).margin(0.02));
}

TEST_CASE("the rock bridges asked for fill each line between its traces, which stay the same",
          "[cutting]") {
  // The set of the test above: asking for the bridges draws nothing more (the traces are
  // bit for bit those drawn without), every bridge lies on its trace's line, and traces and
  // bridges together cover each line's whole length in the box (the box plus its 1 % margin,
  // 0.2 m on each side: 100.4 m), to the round-off of a few hundred sums (1e-9).
  const JointSetSpec set = broken_horizontal_set();
  const std::vector<JointSegment> plain = joint_set_traces(set, {0, 0}, {100, 20}, 7);
  std::vector<JointSegment> bridges;
  const std::vector<JointSegment> traces = joint_set_traces(set, {0, 0}, {100, 20}, 7, &bridges);
  REQUIRE(traces.size() == plain.size());
  for (std::size_t k = 0; k < traces.size(); ++k) {
    CHECK(traces[k].from == plain[k].from);
    CHECK(traces[k].to == plain[k].to);
  }
  std::map<double, double> covered;  // line's y -> traces' and bridges' length on it
  for (const JointSegment& t : traces) covered[t.from.y()] += (t.to - t.from).norm();
  for (const JointSegment& b : bridges) {
    CHECK(b.from.y() == b.to.y());
    CHECK((b.to - b.from).norm() <= 2.0 + 1e-9);
    covered[b.from.y()] += (b.to - b.from).norm();
  }
  REQUIRE(covered.size() == 21);
  for (const auto& [y, length] : covered) CHECK(length == Approx(100.4).margin(1e-9));
}

TEST_CASE("a 200 m x 100 m slope cut by two persistent sets tiles its domain", "[cutting]") {
  // Sets at 30 degrees (spacing 4 m) and 120 degrees (spacing 3 m): parallelograms of
  // 4 x 3 / sin(90) = 12 m^2, about 20000 / 12 = 1670 blocks plus the pieces along the
  // boundary; the slope's face cuts the rectangle's corner. Areas sum to the domain's to
  // 1e-9 (as in cut_domain's tests). Its cost is measured in bench/ (BM_CutSlope).
  const Polygon domain{{0, 0}, {200, 0}, {200, 100}, {80, 100}, {0, 20}};
  JointSetSpec a, b;
  a.dip = 30.0;
  a.spacing = 4.0;
  b.dip = 120.0;
  b.spacing = 3.0;
  std::vector<JointSegment> joints = joint_set_traces(a, {0, 0}, {200, 100}, 1);
  const std::vector<JointSegment> more = joint_set_traces(b, {0, 0}, {200, 100}, 2);
  joints.insert(joints.end(), more.begin(), more.end());
  const CutResult cut = cut_domain(domain, joints);
  const double area = signed_area(domain);
  CHECK(area == Approx(16800.0));  // 20000 less the 80 m x 80 m corner triangle
  double sum = 0.0;
  for (const Polygon& p : cut.blocks) sum += signed_area(p);
  CHECK(sum == Approx(area).epsilon(1e-9));
  CHECK(cut.blocks.size() > area / 12.0);
  CHECK(cut.blocks.size() < 1.3 * area / 12.0);
}

TEST_CASE("a set daylights in a face when it dips out of it less steeply than the face",
          "[cutting][daylight]") {
  // The small slope's 45-degree face, rock on the left from (10, 10) down to (3, 3): it
  // faces -x and up.
  const Vec2 top(10.0, 10.0), toe(3.0, 3.0);
  CHECK(daylights_in_face(25.0, top, toe));    // rises to +x: dips 25 towards -x, out of it
  CHECK(daylights_in_face(44.0, top, toe));
  CHECK_FALSE(daylights_in_face(46.0, top, toe));   // steeper than the face: under its toe
  CHECK_FALSE(daylights_in_face(155.0, top, toe));  // dips 25 towards +x: into the slope
  CHECK_FALSE(daylights_in_face(0.0, top, toe));    // flat
  CHECK_FALSE(daylights_in_face(90.0, top, toe));   // vertical
  CHECK(daylights_in_face(25.0 + 180.0, top, toe)); // a direction and its opposite: one line
  CHECK_FALSE(daylights_in_face(25.0, toe, top));   // the rock on the other side: an overhang
  // A vertical cliff facing -x (rock on the left going down): any dip out of it below 90.
  CHECK(daylights_in_face(80.0, Vec2(0.0, 10.0), Vec2(0.0, 0.0)));
  CHECK_FALSE(daylights_in_face(100.0, Vec2(0.0, 10.0), Vec2(0.0, 0.0)));
  // A flat top has no daylighting set.
  CHECK_FALSE(daylights_in_face(10.0, Vec2(20.0, 10.0), Vec2(10.0, 10.0)));
}
