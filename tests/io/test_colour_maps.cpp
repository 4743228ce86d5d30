// io/colour_maps: the tab10 categories and the viridis anchors.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <tuple>

#include "io/colour_maps.hpp"

using namespace dda;

TEST_CASE("colour maps: tab10 categories and viridis anchors", "[picture][colour]") {
  // Matplotlib's tab10: #1f77b4 blue, #ff7f0e orange, #17becf cyan (index 9).
  CHECK(category_colour(0) == Rgb{0x1f, 0x77, 0xb4});
  CHECK(category_colour(1) == Rgb{0xff, 0x7f, 0x0e});
  CHECK(category_colour(9) == Rgb{0x17, 0xbe, 0xcf});
  CHECK(category_colour(10) == category_colour(0));
  CHECK(category_colour(-1) == category_colour(9));
  std::map<std::tuple<int, int, int>, int> distinct;
  for (int i = 0; i < 10; ++i) {
    const Rgb c = category_colour(i);
    ++distinct[{c.r, c.g, c.b}];
  }
  CHECK(distinct.size() == 10U);

  // Viridis: #440154 at 0, #21918c at 1/2, #fde725 at 1; clamped outside [0, 1].
  CHECK(sequential_colour(0.0) == Rgb{0x44, 0x01, 0x54});
  CHECK(sequential_colour(0.5) == Rgb{0x21, 0x91, 0x8c});
  CHECK(sequential_colour(1.0) == Rgb{0xfd, 0xe7, 0x25});
  CHECK(sequential_colour(-3.0) == sequential_colour(0.0));
  CHECK(sequential_colour(7.0) == sequential_colour(1.0));
  CHECK(sequential_colour(std::nan("")) == sequential_colour(0.0));
  // Half way between the anchors at 0 (68, 1, 84) and 1/4 (59, 82, 139): the means 63.5,
  // 41.5 and 111.5, within the 1/2 of rounding to 8 bits.
  const Rgb mid = sequential_colour(0.125);
  CHECK(std::abs(mid.r - 63.5) <= 0.5);
  CHECK(std::abs(mid.g - 41.5) <= 0.5);
  CHECK(std::abs(mid.b - 111.5) <= 0.5);
  // Viridis gets lighter throughout: the sum of the channels grows with t here.
  int last = -1;
  for (int i = 0; i <= 20; ++i) {
    const Rgb c = sequential_colour(i / 20.0);
    const int sum = c.r + c.g + c.b;
    CHECK(sum > last);
    last = sum;
  }
}
