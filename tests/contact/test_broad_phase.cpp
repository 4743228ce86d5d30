// contact/broad_phase: a polygon's grown box by hand, and the sweep's overlapping pairs
// against brute force. (The narrow phase: test_narrow_phase.cpp.)
#include <algorithm>
#include <catch2/catch.hpp>
#include <random>
#include <utility>
#include <vector>

#include "contact/broad_phase.hpp"
#include "support/geometry_checks.hpp"

using namespace dda;
using test::check_vec;

TEST_CASE("grown_box of a triangle", "[contact-geometry]") {
  // Triangle (0,0) (4,0) (0,3): box [0,4] x [0,3], grown by 0.5: [-0.5,4.5] x [-0.5,3.5].
  const Box b = grown_box({{0, 0}, {4, 0}, {0, 3}}, 0.5);
  check_vec(b.min, -0.5, -0.5);
  check_vec(b.max, 4.5, 3.5);
}

TEST_CASE("overlapping_pairs agrees with a brute-force check on 300 random boxes",
          "[contact-geometry]") {
  // Corners on a grid of 1/4 m (exact binary fractions), so that many boxes touch exactly
  // (shared edges or corners) and some are zero-width or zero-height: touching counts as
  // overlapping, decided by exact comparisons on both sides.
  std::mt19937 rng(20261122u);
  std::uniform_int_distribution<int> pos(0, 120);  // 0 .. 30 m in quarter metres
  std::uniform_int_distribution<int> size(0, 8);   // 0 .. 2 m
  std::vector<Box> boxes;
  for (int i = 0; i < 300; ++i) {
    const int x = pos(rng), y = pos(rng), w = size(rng), h = size(rng);
    boxes.push_back(Box{Vec2(0.25 * x, 0.25 * y), Vec2(0.25 * (x + w), 0.25 * (y + h))});
  }
  // Hand-placed extra cases: two boxes sharing only a corner, two sharing an edge, and two
  // with the same min x (ties in the sweep's sort).
  boxes.push_back(Box{Vec2(40, 40), Vec2(41, 41)});
  boxes.push_back(Box{Vec2(41, 41), Vec2(42, 42)});  // corner (41,41)
  boxes.push_back(Box{Vec2(50, 40), Vec2(51, 41)});
  boxes.push_back(Box{Vec2(51, 40.5), Vec2(52, 43)});  // edge x = 51
  boxes.push_back(Box{Vec2(60, 40), Vec2(61, 41)});
  boxes.push_back(Box{Vec2(60, 41), Vec2(60.5, 45)});  // same min x, touching at y = 41

  std::vector<std::pair<int, int>> brute;
  int touching = 0;
  const int n = static_cast<int>(boxes.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const Box& p = boxes[i];
      const Box& q = boxes[j];
      if (p.min.x() <= q.max.x() && q.min.x() <= p.max.x() && p.min.y() <= q.max.y() &&
          q.min.y() <= p.max.y()) {
        brute.emplace_back(i, j);  // i < j, and pushed in increasing (i, j) order
        if (p.min.x() == q.max.x() || q.min.x() == p.max.x() || p.min.y() == q.max.y() ||
            q.min.y() == p.max.y()) {
          ++touching;
        }
      }
    }
  }
  INFO(brute.size() << " overlapping pairs, " << touching << " of them touching");
  REQUIRE(touching >= 3);  // the test does exercise touching boxes (the 3 placed ones at least)
  REQUIRE(brute.size() > 50);  // and a good number of pairs (about 1e2 expected)
  const std::vector<std::pair<int, int>> got = overlapping_pairs(boxes);
  CHECK(got == brute);
  // Its own contract, independently of the brute force: i < j, strictly increasing.
  for (std::size_t k = 0; k < got.size(); ++k) {
    CHECK(got[k].first < got[k].second);
    if (k > 0) CHECK(got[k - 1] < got[k]);
  }
  // The placed pairs are there.
  CHECK(std::find(got.begin(), got.end(), std::make_pair(300, 301)) != got.end());
  CHECK(std::find(got.begin(), got.end(), std::make_pair(302, 303)) != got.end());
  CHECK(std::find(got.begin(), got.end(), std::make_pair(304, 305)) != got.end());
}

TEST_CASE("overlapping_pairs of a column agrees with a brute-force check", "[contact-geometry]") {
  // 400 unit blocks stacked in y, each touching the next, and every fifth one a little wider
  // so that it also touches a thin block hanging beside the column: the sweep takes y here
  // (along x every box overlaps every other), and must give the same list. Expected pairs:
  // 399 in the column and 80 with the thin blocks beside it (exact touching, on 1/4 m).
  std::vector<Box> boxes;
  for (int i = 0; i < 400; ++i) {
    const double wide = i % 5 == 0 ? 0.25 : 0.0;
    boxes.push_back(Box{Vec2(0, i), Vec2(1 + wide, i + 1)});
  }
  for (int i = 0; i < 400; i += 5) boxes.push_back(Box{Vec2(1.25, i + 0.25), Vec2(1.5, i + 0.75)});
  std::vector<std::pair<int, int>> brute;
  const int n = static_cast<int>(boxes.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (boxes_overlap(boxes[i], boxes[j])) brute.emplace_back(i, j);
    }
  }
  CHECK(brute.size() == 399 + 80);
  CHECK(overlapping_pairs(boxes) == brute);
}

TEST_CASE("overlapping_pairs of no boxes and of one box is empty", "[contact-geometry]") {
  CHECK(overlapping_pairs({}).empty());
  CHECK(overlapping_pairs({Box{Vec2(0, 0), Vec2(1, 1)}}).empty());
}

TEST_CASE("first_overlapping_pair finds the pair a test accepts, and stops there",
          "[contact-geometry]") {
  // 100 000 identical boxes: the first pair met is (0, 1), after one test (listing every
  // pair first, as the scene reader did, is 5e9 pairs).
  std::vector<Box> same(100000, Box{Vec2(0, 0), Vec2(1, 1)});
  int tests = 0;
  auto found = first_overlapping_pair(same, [&](int, int) { return ++tests > 0; });
  REQUIRE(found);
  CHECK(*found == std::pair(0, 1));
  CHECK(tests == 1);

  // A test that accepts nothing sees exactly the pairs overlapping_pairs lists (300 random
  // boxes on a 1/4 m grid, many touching), each once, with i < j.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> corner(0, 40), size(0, 8);
  std::vector<Box> boxes;
  for (int k = 0; k < 300; ++k) {
    const Vec2 lo(0.25 * corner(rng), 0.25 * corner(rng));
    boxes.push_back({lo, lo + Vec2(0.25 * size(rng), 0.25 * size(rng))});
  }
  std::vector<std::pair<int, int>> seen;
  found = first_overlapping_pair(boxes, [&](int i, int j) {
    seen.emplace_back(i, j);
    return false;
  });
  CHECK_FALSE(found);
  std::sort(seen.begin(), seen.end());
  CHECK(seen == overlapping_pairs(boxes));

  // A column of 2000 unit boxes stacked along y (each touching the next) is swept along y:
  // each box meets only the one above it, 1999 tests, not the 2e6 pairs side by side in x.
  std::vector<Box> column;
  for (int k = 0; k < 2000; ++k) column.push_back({Vec2(0, k), Vec2(1, k + 1)});
  tests = 0;
  found = first_overlapping_pair(column, [&](int i, int j) {
    ++tests;
    return i == 1000 && j == 1001;
  });
  REQUIRE(found);
  CHECK(*found == std::pair(1000, 1001));
  CHECK(tests == 1001);
  // Fewer than two boxes: no pair.
  CHECK_FALSE(first_overlapping_pair({}, [](int, int) { return true; }));
  CHECK_FALSE(first_overlapping_pair({Box{Vec2(0, 0), Vec2(1, 1)}}, [](int, int) { return true; }));
}
