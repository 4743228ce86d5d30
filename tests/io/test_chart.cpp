// io/chart: round tick values, data landing on their pixels, a log axis, bands and vertical
// lines where their x says, and the errors. Pixel positions are checked against the frame
// the chart reports, and that frame against the ticks it must hold.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "io/chart.hpp"
#include "support/picture_checks.hpp"

using namespace dda;
using namespace dda::test::picture;

namespace {

// A series built field by field (GCC 12 warns, a false -Wrestrict, on aggregate
// initialisation of the label from a literal).
ChartSeries series(const char* label, std::vector<double> x, std::vector<double> y, Rgb colour,
                   double width, bool markers) {
  ChartSeries s;
  s.label = label;
  s.x = std::move(x);
  s.y = std::move(y);
  s.colour = colour;
  s.line_width = width;
  s.markers = markers;
  return s;
}

}  // namespace

TEST_CASE("chart: ticks are round numbers covering the range", "[picture][chart]") {
  // 0..1 in at most 6 steps: 0.2 apart (0.1 would need 10).
  const std::vector<double> a = nice_ticks(0.0, 1.0, 6);
  REQUIRE(a.size() == 6);
  CHECK(a.front() == 0.0);
  CHECK(a.back() == Approx(1.0).margin(1e-12));
  CHECK(a[1] == Approx(0.2).margin(1e-12));
  // -3.7..12.2 in at most 8: step 5 would give 5 ticks (-5..15), 2 gives 10 steps (too many).
  const std::vector<double> b = nice_ticks(-3.7, 12.2, 8);
  CHECK(b.front() == -5.0);
  CHECK(b.back() == 15.0);
  CHECK(b.size() == 5);
  // A range of one value is widened around it.
  const std::vector<double> c = nice_ticks(2.0, 2.0, 5);
  CHECK(c.front() <= 1.8);
  CHECK(c.back() >= 2.2);
  CHECK_THROWS_AS(nice_ticks(0.0, NAN, 5), std::invalid_argument);
}

TEST_CASE("chart: points land on their pixels, bands and lines where their x says", "[picture][chart]") {
  ChartOptions o;
  o.width_px = 900;
  o.height_px = 500;
  o.title = "trials";
  o.x_label = "factor F";
  o.y_label = "u (m)";
  o.series = {series("u", {0.0, 10.0}, {0.0, 10.0}, kRed, 3.0, false),
              series("trials", {2.0, 8.0}, {6.0, 4.0}, kBlue, 0.0, true)};
  o.bands.resize(1);
  o.bands[0].from = 4.0;
  o.bands[0].to = 5.0;
  o.bands[0].colour = Rgb{0, 200, 0};
  o.bands[0].label = "bracket";
  o.vertical_lines.resize(1);
  o.vertical_lines[0].x = 7.0;
  o.vertical_lines[0].colour = Rgb{200, 0, 200};
  o.vertical_lines[0].label = "factor F";
  const ChartFrame f = chart_frame(o);
  // The data 0..10 on both axes, with markers: the axes run 3 % beyond them (0.3), the round
  // ticks 0, 2, ..., 10 inside.
  CHECK(f.xmin == Approx(-0.3));
  CHECK(f.xmax == Approx(10.3));
  CHECK(f.ymin == Approx(-0.3));
  CHECK(f.ymax == Approx(10.3));
  CHECK(f.x_ticks.size() == 6);
  CHECK(f.x_ticks.front() == 0.0);
  const Image img = draw_chart(o);
  CHECK(img.width == 900);
  CHECK(img.height == 500);
  // The red line y = x passes through the pixel of (3, 3) (3 px wide, so its neighbours too).
  const Vec2 p = f.to_pixel(3.0, 3.0);
  CHECK(img.at(static_cast<int>(p.x()), static_cast<int>(p.y())) == kRed);
  const Vec2 q = f.to_pixel(3.0, 6.0);  // above the line, no band there: white or grid
  CHECK(img.at(static_cast<int>(q.x()), static_cast<int>(q.y())) != kRed);
  // A marker's square is centred on its point: at least 7 x 7 blue pixels around (2, 6).
  const Vec2 m = f.to_pixel(2.0, 6.0);
  for (int dx = -3; dx <= 3; ++dx)
    for (int dy = -3; dy <= 3; ++dy) CHECK(img.at(static_cast<int>(m.x()) + dx, static_cast<int>(m.y()) + dy) == kBlue);
  // The band fills x in [4, 5] at any height where nothing is drawn over it.
  const Vec2 band = f.to_pixel(4.5, 9.0);
  CHECK(img.at(static_cast<int>(band.x()), static_cast<int>(band.y())) == (Rgb{0, 200, 0}));
  CHECK(img.at(static_cast<int>(f.to_pixel(5.5, 9.0).x()), static_cast<int>(band.y())) != (Rgb{0, 200, 0}));
  // The dashed line at x = 7: its colour in the column over the plot's height, dashes 5 of
  // every 8 rows.
  const int x7 = static_cast<int>(std::lround(f.to_pixel(7.0, 0.0).x()));
  int on = 0;
  for (int y = f.top; y < f.top + f.height; ++y) on += img.at(x7, y) == (Rgb{200, 0, 200});
  CHECK(on == Approx(f.height * 5.0 / 8.0).margin(6));
  // The legend's swatches: red, blue, green, magenta all present below the plot area.
  for (Rgb c : {kRed, kBlue, Rgb{0, 200, 0}, Rgb{200, 0, 200}}) {
    int below = 0;
    for (int y = f.top + f.height + 1; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) below += img.at(x, y) == c;
    CHECK(below >= 49);  // a 7 x 7 swatch at least (text scale 2: 14 x 14)
  }
}

TEST_CASE("chart: a log axis runs over whole decades and skips values <= 0 (a line: no room added for markers)", "[picture][chart]") {
  ChartOptions o;
  o.log_y = true;
  o.series = {series("u", {1.0, 2.0, 3.0, 4.0}, {2e-5, 0.0, 3e-3, 0.5}, kRed, 2.0, false)};
  const ChartFrame f = chart_frame(o);
  CHECK(f.ymin == -5.0);  // log10 of 1e-5, the decade below 2e-5
  CHECK(f.ymax == 0.0);   // 1e0, the decade above 0.5
  const Image img = draw_chart(o);
  const Vec2 p = f.to_pixel(3.0, 3e-3);
  CHECK(p.y() == Approx(f.top + f.height * (1.0 - (std::log10(3e-3) + 5.0) / 5.0)));
  CHECK(img.at(static_cast<int>(p.x()), static_cast<int>(p.y())) == kRed);
}

TEST_CASE("chart: errors name what is wrong", "[picture][chart]") {
  ChartOptions o;
  CHECK_THROWS_WITH(chart_frame(o), Catch::Matchers::Contains("no finite point"));
  o.series = {series("s", {1.0, 2.0}, {1.0}, kRed, 2.0, false)};
  CHECK_THROWS_WITH(chart_frame(o), Catch::Matchers::Contains("series 's' has 2 x values and 1 y values"));
  o.series = {series("s", {1.0, 2.0}, {1.0, 2.0}, kRed, 2.0, false)};
  o.width_px = 100;
  CHECK_THROWS_AS(chart_frame(o), std::invalid_argument);
}
