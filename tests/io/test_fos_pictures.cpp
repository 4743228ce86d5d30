// io/fos_pictures: a trial whose one free block moved along a known vector is drawn with that
// block displaced along it, outlined, numbered and with an arrow pointing the way it moved;
// the trials' chart puts stable and failing trials on their side of the bracket. Pixels are
// read back from the written PNG files with the tests' own decoder.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <tuple>

#include "io/fos_pictures.hpp"
#include "solver/world.hpp"
#include "support/picture_checks.hpp"
#include "support/scene_builders.hpp"

using namespace dda;
namespace pic = dda::test::picture;

namespace {

Rgb pixel(const pic::Decoded& d, const Vec2& p) {
  const std::size_t i = (static_cast<std::size_t>(p.y()) * d.width + static_cast<std::size_t>(p.x())) * 3;
  return {d.pixels.at(i), d.pixels.at(i + 1), d.pixels.at(i + 2)};
}

// A fixed base `length` x `depth` m (its top at y = 1) and a free 2 x 1 m block on it.
World two_blocks(double length = 10.0, double depth = 1.0) {
  Scene s = dda::test::base_scene(1, 0.01);
  BlockSpec base = dda::test::block(dda::test::rectangle(0.0, 1.0 - depth, length, depth));
  base.fixed = true;
  s.blocks = {base, dda::test::block(dda::test::rectangle(4.0, 1.0, 2.0, 1.0))};
  return make_world(s);
}

}  // namespace

TEST_CASE("fos pictures: the moved block drawn displaced along its motion, outlined, numbered, "
          "with an arrow the way it went",
          "[picture][fos]") {
  const World before = two_blocks();
  TrialResult t;
  t.factor = 1.25;
  t.verdict = "still moving at the end";
  t.world = before;
  // Down the slope's way and a little down: 4 mm, unrotated.
  const Vec2 u(-0.0036, -0.0018);
  Block& moving = t.world.blocks[1];
  for (Vec2& v : moving.vertices) v += u;
  moving.moments.centroid += u;

  const SlopePicture p = mechanism_picture(before, t, "first failing trial");
  const PictureFrame f = picture_frame(p.blocks, p.options);
  pic::TempFile file("fos_mechanism");
  write_block_picture(file.path.string(), p.blocks, p.options);
  const pic::Decoded d = pic::decode_png(pic::read_file(file.path));
  REQUIRE(d.width == 1600U);

  // The drawn displacement is a quarter of the typical block's size: 0.25 sqrt(2 m^2) along u.
  const Vec2 c = before.blocks[1].moments.centroid;
  const Vec2 drawn = 0.25 * std::sqrt(2.0) * u.normalized();
  // A point inside the displaced block, away from its label (at its centre) and its arrow
  // (along u from the old centre): the colour of the largest displacement, viridis' end.
  const Vec2 inside = c + drawn + Vec2(0.6, 0.3);
  CHECK(pixel(d, f.to_pixel(inside)) == sequential_colour(1.0));
  // The same point of the block's old place that the displaced block no longer covers is
  // the pale colour of a free block at rest: along -u from the old corner's inside.
  const Vec2 old_corner_inside = Vec2(5.95, 1.95);  // near the old top-right corner
  CHECK(pixel(d, f.to_pixel(old_corner_inside)) == (Rgb{235, 235, 235}));
  // The outline: dark red pixels all round the displaced block (3 px wide: more than the
  // perimeter of 6 m at the picture's scale).
  int outline = 0;
  for (std::size_t i = 0; i < d.pixels.size(); i += 3)
    outline += d.pixels[i] == 120 && d.pixels[i + 1] == 0 && d.pixels[i + 2] == 0;
  CHECK(outline > 2 * 6.0 * f.scale);
  // The arrow: red pixels along u from the old centroid, at 0.3 and 0.8 of its length, and
  // none along -u (it points the way the block went).
  const double arrow = 3.2 * 0.25 * std::sqrt(2.0);
  for (double share : {0.3, 0.8}) {
    const Vec2 at = f.to_pixel(c + share * arrow * u.normalized());
    int red = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) red += pixel(d, at + Vec2(dx, dy)) == (Rgb{200, 0, 0});
    CHECK(red >= 2);  // a 2 px shaft through a 3 x 3 neighbourhood
  }
  const Vec2 back = f.to_pixel(c - 0.5 * arrow * u.normalized());
  CHECK(pixel(d, back) != (Rgb{200, 0, 0}));
  // The block's number, "1", on a white box at the displaced centroid.
  REQUIRE(p.options.labels.size() == 1);
  CHECK(p.options.labels[0].text == "1");
  CHECK((p.options.labels[0].at - (c + drawn)).norm() < 1e-12);
  // Axes in metres: the picture has them, and the size of a slope picture is far below 1 MB.
  CHECK(p.options.axes);
  CHECK(pic::read_file(file.path).size() < 100000U);
}

TEST_CASE("fos pictures: the trials' chart puts each trial at its F on its side of the bracket",
          "[picture][fos]") {
  FosResult r;
  r.found = true;
  r.last_stable = 1.2;
  r.first_failing = 1.3;
  r.factor_of_safety = 1.25;
  for (const auto& [factor, stable, u] : {std::tuple{1.0, true, 1e-4}, std::tuple{2.0, false, 0.5},
                                          std::tuple{1.2, true, 3e-4}, std::tuple{1.3, false, 0.2}}) {
    TrialResult t;
    t.factor = factor;
    t.stable = stable;
    t.largest_displacement = u;
    r.trials.push_back(t);
  }
  const ChartOptions o = trials_chart(r, 0.1, nullptr);
  const ChartFrame f = chart_frame(o);
  const Image img = draw_chart(o);
  const Rgb blue{31, 119, 180}, red{200, 0, 0};
  CHECK(img.at(static_cast<int>(f.to_pixel(1.0, 1e-4).x()), static_cast<int>(f.to_pixel(1.0, 1e-4).y())) == blue);
  CHECK(img.at(static_cast<int>(f.to_pixel(2.0, 0.5).x()), static_cast<int>(f.to_pixel(2.0, 0.5).y())) == red);
  // The bracket's band between 1.2 and 1.3, above the points and the failure line.
  const Vec2 band = f.to_pixel(1.22, 0.02);  // (0.01 is a grid line)
  CHECK(img.at(static_cast<int>(band.x()), static_cast<int>(band.y())) == (Rgb{255, 221, 150}));
  const Vec2 out = f.to_pixel(1.5, 0.02);
  CHECK(img.at(static_cast<int>(out.x()), static_cast<int>(out.y())) != (Rgb{255, 221, 150}));
  // The factor of safety's dashed line at 1.25 in its colour (black) somewhere in its column.
  const int x = static_cast<int>(std::lround(f.to_pixel(1.25, 1.0).x()));
  int black = 0;
  for (int y = f.top; y < f.top + f.height; ++y) black += img.at(x, y) == (Rgb{0, 0, 0});
  CHECK(black > f.height / 2);
}

TEST_CASE("fos pictures: a close-up around moving blocks that are small on the slope", "[picture][fos]") {
  TrialResult t;
  t.factor = 1.1;
  t.verdict = "still moving at the end";
  const Vec2 u(-0.002, 0.0);
  SECTION("a 2 m block on a 10 m base is not small: no close-up") {
    const World before = two_blocks();
    t.world = before;
    for (Vec2& v : t.world.blocks[1].vertices) v += u;
    t.world.blocks[1].moments.centroid += u;
    const SlopePicture p = mechanism_picture(before, t, "trial");
    CHECK(p.moving_from == 2);
    CHECK_FALSE(close_up(p));
  }
  SECTION("on a 100 x 10 m base it is: the close-up leaves the base out (its middle is 45 m away)") {
    const World before = two_blocks(100.0, 10.0);
    t.world = before;
    for (Vec2& v : t.world.blocks[1].vertices) v += u;
    t.world.blocks[1].moments.centroid += u;
    const SlopePicture p = mechanism_picture(before, t, "trial");
    CHECK(p.typical_size == Approx(std::sqrt(2.0)).epsilon(1e-12));  // the one free block's 2 m^2
    const std::optional<SlopePicture> close = close_up(p);
    REQUIRE(close);
    // The free block where it was (its middle at (5, 1.5), in the region) and moved; not the base.
    CHECK(close->blocks.size() == 2);
    CHECK(close->moving_from == 1);
    CHECK(close->options.labels.size() == 1);
    CHECK(close->options.arrows.size() == 1);
    const PictureFrame f = picture_frame(close->blocks, close->options);
    // About 1600 px over the 2.6 m the two drawn blocks span: far closer than 16 px/m.
    CHECK(f.scale > 300.0);
  }
}
