// Line and scatter charts as PNG pictures, drawn with the same rasteriser and bitmap font as
// the block pictures: axes with round ticks and their values, axis labels, several series
// (lines, markers or both) with a legend, shaded vertical bands and vertical lines (a
// bracket and the value found in it). For a run's energy account and monitor histories and
// for a factor-of-safety search's trials. Pure functions of plain data, except write_chart.
#pragma once

#include <string>
#include <vector>

#include "io/image.hpp"
#include "kinematics/types.hpp"

namespace dda {

struct ChartSeries {
  std::string label;      // in the legend; an empty label keeps the series out of it
  std::vector<double> x;  // as many as y; points with a non-finite coordinate are skipped
  std::vector<double> y;  // (and on a log axis, y <= 0), breaking the line there
  Rgb colour = {31, 119, 180};
  double line_width = 2.0;  // pixels; 0 draws no line
  bool markers = false;     // a filled square of 4 line widths (at least 7 px) at each point
};

// A shaded band over the whole height of the plot area between two x values.
struct ChartBand {
  double from = 0.0;
  double to = 0.0;
  Rgb colour = {225, 225, 225};
  std::string label;  // in the legend when not empty
};

// A vertical line over the whole height of the plot area, 1 px, dashed.
struct ChartVerticalLine {
  double x = 0.0;
  Rgb colour = {0, 0, 0};
  std::string label;  // in the legend when not empty
};

struct ChartOptions {
  int width_px = 1000;
  int height_px = 560;
  std::string title;    // centred above the plot
  std::string x_label;  // centred under the x tick values
  std::string y_label;  // above the y axis, left-aligned (the font does not turn)
  bool log_y = false;   // decades on y; only y > 0 are drawn
  std::vector<ChartSeries> series;
  std::vector<ChartBand> bands;
  std::vector<ChartVerticalLine> vertical_lines;
};

// Where the data land: the plot area's pixel box and the axes' ranges (round tick values
// around the data, from 0 when the data are all of one sign and near it).
struct ChartFrame {
  int left = 0;
  int top = 0;
  int width = 0;
  int height = 0;
  double xmin = 0.0, xmax = 1.0;
  double ymin = 0.0, ymax = 1.0;  // on a log axis, log10 of the values
  bool log_y = false;
  std::vector<double> x_ticks, y_ticks;  // values (log10 ones on a log axis)
  // The pixel of a data point (y its value, not its logarithm).
  Vec2 to_pixel(double x, double y) const;
};

// Round numbers (1, 2 or 5 times a power of ten apart) from at or below `lo` to at or above
// `hi`, at most `at_most` + 1 of them (at_most >= 2). lo == hi gives a range around them.
std::vector<double> nice_ticks(double lo, double hi, int at_most);

// `ticks` less those outside [lo, hi]; a tick off by round-off (1e-9 of the values' size)
// stays. For an axis that runs over the data rather than over round ticks.
std::vector<double> ticks_within(std::vector<double> ticks, double lo, double hi);

// The frame draw_chart uses. Throws std::invalid_argument when there is no finite point to
// draw, a series' x and y differ in length, or the picture is smaller than 200 x 150 px.
ChartFrame chart_frame(const ChartOptions& options);

Image draw_chart(const ChartOptions& options);

// draw_chart written as a PNG file (whole, or not at all). Throws std::runtime_error naming
// the path when it cannot be written.
void write_chart(const std::string& path, const ChartOptions& options);

}  // namespace dda
