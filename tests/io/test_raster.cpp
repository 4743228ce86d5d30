// io/raster: pixel counts of the rasteriser against exact areas, and lines pixel by pixel.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "io/raster.hpp"
#include "support/picture_checks.hpp"

using namespace dda;
using namespace dda::test::picture;

TEST_CASE("raster: a polygon paints the pixels whose centres it contains", "[picture][raster]") {
  SECTION("axis-aligned squares paint exactly their area") {
    // Integer corners: [2, 12) x [3, 13) holds the centres of exactly 10 x 10 pixels.
    Image img(20, 20, kWhite);
    fill_polygon(img, rectangle(2, 3, 12, 13), kRed);
    CHECK(count(img, kRed) == 100);
    CHECK(img.at(2, 3) == kRed);
    CHECK(img.at(11, 12) == kRed);
    CHECK(img.at(12, 12) == kWhite);
    CHECK(img.at(11, 13) == kWhite);
    // Shifted by 0.3 px: centres 2.5 .. 11.5 are still the 10 inside [2.3, 12.3).
    Image shifted(20, 20, kWhite);
    fill_polygon(shifted, rectangle(2.3, 3.3, 12.3, 13.3), kRed);
    CHECK(count(shifted, kRed) == 100);
  }
  SECTION("a rotated square paints its area to within its boundary pixels") {
    // A square of side 40 turned by 30 degrees, centred in a 100 x 100 image: area 1600 px.
    // Only pixels cut by the boundary can be miscounted; their number is at most the
    // perimeter times sqrt(2) (a pixel's largest extent across a line) plus the corners,
    // 4 * 40 * 1.42 + 4 < 232.
    const double c = std::cos(std::numbers::pi / 6);
    const double s = std::sin(std::numbers::pi / 6);
    Polygon square;
    for (const auto& [u, v] : {std::pair{-20.0, -20.0}, {20.0, -20.0}, {20.0, 20.0}, {-20.0, 20.0}})
      square.push_back({50.0 + c * u - s * v, 50.0 + s * u + c * v});
    Image img(100, 100, kWhite);
    fill_polygon(img, square, kRed);
    CHECK(std::abs(count(img, kRed) - 1600) < 232);
  }
  SECTION("a concave L leaves its notch empty") {
    // L = [0, 20) x [0, 20) minus the quadrant [10, 20) x [0, 10) (pixel y down): 300 px.
    const Polygon ell = {{0, 0}, {10, 0}, {10, 10}, {20, 10}, {20, 20}, {0, 20}};
    Image img(20, 20, kWhite);
    fill_polygon(img, ell, kRed);
    CHECK(count(img, kRed) == 300);
    CHECK(img.at(15, 5) == kWhite);
    CHECK(img.at(5, 5) == kRed);
    CHECK(img.at(15, 15) == kRed);
  }
  SECTION("polygons sharing an edge paint disjoint pixels that tile their union") {
    // The square [0, 30)^2 cut along its diagonal: the two triangles paint 900 pixels
    // between them, none twice, whatever happens on the diagonal.
    const Polygon lower = {{0, 0}, {30, 0}, {30, 30}};
    const Polygon upper = {{0, 0}, {30, 30}, {0, 30}};
    Image a(30, 30, kWhite);
    Image b(30, 30, kWhite);
    fill_polygon(a, lower, kRed);
    fill_polygon(b, upper, kBlue);
    int both = 0;
    int either = 0;
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 30; ++x) {
        both += a.at(x, y) == kRed && b.at(x, y) == kBlue;
        either += a.at(x, y) == kRed || b.at(x, y) == kBlue;
      }
    CHECK(both == 0);
    CHECK(either == 900);
  }
  SECTION("drawing off the image is clipped") {
    Image img(10, 10, kWhite);
    fill_polygon(img, rectangle(-5, -5, 5, 15), kRed);
    CHECK(count(img, kRed) == 50);  // [0, 5) x [0, 10)
  }
}

TEST_CASE("raster: lines include both end pixels and step once per pixel", "[picture][raster]") {
  Image img(20, 20, kWhite);
  draw_line(img, {2.5, 4.5}, {12.5, 4.5}, kRed);  // horizontal: pixels 2..12 of row 4
  CHECK(count(img, kRed) == 11);
  CHECK(img.at(2, 4) == kRed);
  CHECK(img.at(12, 4) == kRed);
  Image diag(20, 20, kWhite);
  draw_line(diag, {15.2, 1.7}, {3.9, 18.1}, kRed);  // from pixel (15, 1) to (3, 18)
  // A Bresenham line paints one pixel per step along its major axis: 18 - 1 + 1 = 18.
  CHECK(count(diag, kRed) == 18);
  CHECK(diag.at(15, 1) == kRed);
  CHECK(diag.at(3, 18) == kRed);
}

TEST_CASE("raster: a thick line covers its rectangle and squares at its ends", "[picture][raster]") {
  // Horizontal, 4 px wide, from x = 10 to 30 at y = 20: the band [8, 32) x [18, 22) (the end
  // squares reach half the width past each end), 24 x 4 = 96 pixel centres inside.
  Image img(40, 40, kWhite);
  draw_thick_line(img, {10.0, 20.0}, {30.0, 20.0}, 4.0, kRed);
  CHECK(count(img, kRed) == 96);
  CHECK(img.at(8, 18) == kRed);
  CHECK(img.at(31, 21) == kRed);
  CHECK(img.at(7, 20) == kWhite);
  CHECK(img.at(20, 22) == kWhite);
  // Diagonal at 45 degrees, 6 px wide: the band's pixels lie within 3 px of the segment's line
  // (y = x) and none of them farther than half the width plus a pixel's half diagonal.
  Image diag(60, 60, kWhite);
  draw_thick_line(diag, {10.0, 10.0}, {50.0, 50.0}, 6.0, kBlue);
  int far = 0;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 60; ++x)
      if (diag.at(x, y) == kBlue && std::abs((x + 0.5) - (y + 0.5)) / std::sqrt(2.0) > 3.0 + 0.71) ++far;
  CHECK(far == 0);
  CHECK(diag.at(30, 30) == kBlue);
  CHECK(diag.at(31, 29) == kBlue);  // 1.4 px off the line: inside the 3 px half width
  // Width 1 is the Bresenham line: 11 pixels from 2 to 12.
  Image thin(20, 20, kWhite);
  draw_thick_line(thin, {2.5, 4.5}, {12.5, 4.5}, 1.0, kRed);
  CHECK(count(thin, kRed) == 11);
}
