// io/block_picture: the layout of block pictures (blocks at their size, shape and colour;
// title, legend and colour bar), read back through the PNG reader of
// support/picture_checks.hpp. (The PNG writer, rasteriser, font and colour maps under it:
// test_png_writer.cpp, test_raster.cpp, test_bitmap_font.cpp, test_colour_maps.cpp.)
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "io/block_picture.hpp"
#include "io/colour_maps.hpp"
#include "io/image.hpp"
#include "support/picture_checks.hpp"

using namespace dda;
using namespace dda::test::picture;

TEST_CASE("block picture: blocks land at their size, shape and colour", "[picture][blocks]") {
  PictureOptions o;
  o.width_px = 200;

  SECTION("a unit square fills its area in pixels") {
    const std::vector<PictureBlock> blocks = {{rectangle(0, 0, 1, 1), kRed}};
    const PictureFrame f = picture_frame(blocks, o);
    // Margins of max(8, 200 / 50) = 8 px each side: 184 px per metre.
    CHECK(f.scale == Approx(184.0).epsilon(1e-12));  // exact up to rounding of one division
    const Image img = draw_blocks(blocks, o);
    CHECK(img.width == 200);
    CHECK(img.height == f.height);
    CHECK(img.pixels.size() == 3U * 200U * static_cast<std::size_t>(f.height));
    // Fill plus outline covers the square's 184^2 px to within its boundary pixels: the
    // outline may sit on a pixel row or column just outside the filled ones, 4 * 185 at most.
    const double area = f.scale * f.scale;
    const int painted = count(img, kRed) + count(img, o.edge);
    CHECK(std::abs(painted - area) <= 4 * (f.scale + 1));
    // The interior keeps its fill: the outline takes at most one pixel ring of the filled ones.
    CHECK(count(img, kRed) >= (f.scale - 2) * (f.scale - 2));
    // The square's centre (0.5, 0.5) m is red.
    const Vec2 centre = f.to_pixel({0.5, 0.5});
    CHECK(img.at(static_cast<int>(centre.x()), static_cast<int>(centre.y())) == kRed);
  }

  SECTION("equal scales in x and y: a 2 m x 1 m block is twice as wide as tall") {
    const std::vector<PictureBlock> blocks = {{rectangle(10, 5, 12, 6), kRed}};
    const Image img = draw_blocks(blocks, o);
    int xmin = img.width, xmax = -1, ymin = img.height, ymax = -1;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        if (img.at(x, y) == kRed) {
          xmin = std::min(xmin, x);
          xmax = std::max(xmax, x);
          ymin = std::min(ymin, y);
          ymax = std::max(ymax, y);
        }
    const int w = xmax - xmin + 1;
    const int h = ymax - ymin + 1;
    // 2 m at 92 px per metre; the outline may cover one filled column.
    CHECK(std::abs(w - 184) <= 1);
    // Each extent may lose one pixel to the outline: w / h = 2 to within 2 px of w.
    CHECK(std::abs(w - 2 * h) <= 2);
  }

  SECTION("a concave L-shaped block leaves its notch unfilled") {
    // L = [0, 2] x [0, 2] minus the upper-right quadrant (1, 2] x (1, 2].
    const Polygon ell = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    const std::vector<PictureBlock> blocks = {{ell, kRed}};
    const PictureFrame f = picture_frame(blocks, o);
    const Image img = draw_blocks(blocks, o);
    const auto at = [&](double x, double y) {
      const Vec2 p = f.to_pixel({x, y});
      return img.at(static_cast<int>(p.x()), static_cast<int>(p.y()));
    };
    CHECK(at(1.5, 1.5) == o.background);
    CHECK(at(0.5, 1.5) == kRed);
    CHECK(at(1.5, 0.5) == kRed);
    CHECK(at(0.5, 0.5) == kRed);
    // Three quarters of the 2 m x 2 m box, 3 m^2 at 92 px per metre, within the boundary
    // pixels of its 8 m perimeter (8 * 92 + 6 corners).
    const int painted = count(img, kRed) + count(img, o.edge);
    CHECK(std::abs(painted - 3.0 * f.scale * f.scale) <= 8 * f.scale + 6);
  }

  SECTION("two adjacent blocks of different colours both appear, equally") {
    const std::vector<PictureBlock> blocks = {{rectangle(0, 0, 1, 1), kRed},
                                              {rectangle(1, 0, 2, 1), kBlue}};
    const PictureFrame f = picture_frame(blocks, o);
    const Image img = draw_blocks(blocks, o);
    const Vec2 left = f.to_pixel({0.5, 0.5});
    const Vec2 right = f.to_pixel({1.5, 0.5});
    CHECK(img.at(static_cast<int>(left.x()), static_cast<int>(left.y())) == kRed);
    CHECK(img.at(static_cast<int>(right.x()), static_cast<int>(right.y())) == kBlue);
    // Same size: the counts differ at most by the one outline column the shared edge or the
    // right edge takes from one of them (f.scale + 1 px).
    CHECK(std::abs(count(img, kRed) - count(img, kBlue)) <= f.scale + 1);
    CHECK(count(img, kRed) > 0.9 * f.scale * f.scale);  // each at least 90 % filled
  }
}

TEST_CASE("block picture: title, legend and colour bar are drawn, width as asked", "[picture][blocks]") {
  const std::vector<PictureBlock> blocks = {{rectangle(0, 0, 4, 1), kRed}};
  PictureOptions plain;
  plain.width_px = 777;
  PictureOptions full = plain;
  full.title = "Slope, t = 1.5 s";
  const Rgb legend_colour{1, 2, 3};  // used nowhere else
  full.legend = {{"rock", legend_colour}, {"clay (soft)", kBlue}};
  full.colour_bar = ColourBar{"displacement (m)", 0.0, 0.0125};

  const Image a = draw_blocks(blocks, plain);
  const Image b = draw_blocks(blocks, full);
  CHECK(a.width == 777);
  CHECK(b.width == 777);
  CHECK(b.height > a.height);  // the extras add rows, not width
  CHECK(count(a, plain.text) == 0);
  CHECK(count(b, full.text) > 0);
  // The legend's swatch: 7 px of cap height at text scale 777 / 600 = 1, less its outline.
  CHECK(count(b, legend_colour) == 5 * 5);
  // The colour bar shows the sequential map's first and last colours.
  CHECK(count(b, sequential_colour(0.0)) > 0);
  CHECK(count(b, sequential_colour(1.0)) > 0);
  // The blocks keep their scale: the title goes above, the rest below.
  CHECK(picture_frame(blocks, full).scale == picture_frame(blocks, plain).scale);

  CHECK_THROWS_AS(draw_blocks({}, plain), std::invalid_argument);
  CHECK_THROWS_AS(draw_blocks({{{{1, 1}, {1, 1}, {1, 1}}, kRed}}, plain), std::invalid_argument);
  CHECK_THROWS_AS(draw_blocks({{{{0, 0}, {std::nan(""), 1.0}, {1, 1}}, kRed}}, plain), std::invalid_argument);
  TempFile file("blocks");
  write_block_picture(file.path.string(), blocks, full);
  const Decoded d = decode_png(read_file(file.path));
  CHECK(d.width == 777U);
  CHECK(d.pixels == b.pixels);
}

TEST_CASE("block picture: an arrow lies along its vector with a head at its end, and a label "
          "sits on a white box at its point",
          "[picture][blocks]") {
  PictureOptions o;
  o.width_px = 200;  // 184 px per metre over a unit square (margins of 8 px)
  const std::vector<PictureBlock> blocks = {{rectangle(0, 0, 1, 1), kRed}};
  const PictureFrame f = picture_frame(blocks, o);
  const Rgb arrow{0, 0, 255};

  SECTION("a horizontal arrow") {
    o.arrows.push_back({{0.2, 0.5}, {0.8, 0.5}, arrow});
    const Image img = draw_blocks(blocks, o);
    const Vec2 from = f.to_pixel({0.2, 0.5}), to = f.to_pixel({0.8, 0.5});
    const int row = static_cast<int>(from.y());
    // The shaft: every pixel from its tail to its tip on the arrow's row (Bresenham on a
    // horizontal line is exact).
    int on_shaft = 0;
    for (int x = static_cast<int>(from.x()); x <= static_cast<int>(to.x()); ++x) {
      on_shaft += img.at(x, row) == arrow ? 1 : 0;
    }
    CHECK(on_shaft == static_cast<int>(to.x()) - static_cast<int>(from.x()) + 1);
    // The head: 12 px strokes (a third of 110 px, capped at 12) back from the tip at 30
    // degrees, so 6 px above and below the shaft 10 px behind the tip, give or take a pixel
    // of Bresenham's rounding.
    int head = 0;
    for (int dy = -8; dy <= 8; ++dy) {
      if (std::abs(dy) < 4) continue;
      for (int dx = -12; dx <= -8; ++dx) head += img.at(static_cast<int>(to.x()) + dx, row + dy) == arrow ? 1 : 0;
    }
    CHECK(head >= 4);
    // Nothing of the arrow behind its tail.
    int behind = 0;
    for (int x = 0; x < static_cast<int>(from.x()) - 1; ++x) behind += img.at(x, row) == arrow ? 1 : 0;
    CHECK(behind == 0);
  }

  SECTION("a label") {
    o.labels.push_back({{0.5, 0.5}, "17", Rgb{0, 0, 0}});
    const Image img = draw_blocks(blocks, o);
    const Vec2 c = f.to_pixel({0.5, 0.5});
    // Text scale 1 at 200 px (the title's is also 1, and labels use one less, at least 1):
    // two glyphs, 11 x 9 px, on a white box one pixel larger all round, centred on the point.
    int white = 0, black = 0;
    for (int y = static_cast<int>(c.y()) - 7; y <= static_cast<int>(c.y()) + 7; ++y) {
      for (int x = static_cast<int>(c.x()) - 8; x <= static_cast<int>(c.x()) + 8; ++x) {
        white += img.at(x, y) == Rgb{255, 255, 255} ? 1 : 0;
        black += img.at(x, y) == Rgb{0, 0, 0} ? 1 : 0;
      }
    }
    CHECK(black > 10);                  // the digits' strokes
    CHECK(white + black == 13 * 11);    // the box: 13 x 11 px, each pixel white or ink
  }
}
