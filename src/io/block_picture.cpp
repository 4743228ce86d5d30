// Layout, top to bottom: margin, title, blocks, legend, colour bar, margin. The blocks are
// filled first and outlined afterwards, so a shared edge is drawn once over both neighbours.
#include "io/block_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "io/bitmap_font.hpp"
#include "io/chart.hpp"
#include "io/picture_layout.hpp"
#include "io/png_writer.hpp"
#include "io/raster.hpp"

namespace dda {
namespace {

// An axis value with the decimals its ticks' step needs (none for whole metres). Always
// fixed-point, unlike a chart's tick values (io/chart): a coordinate such as a northing of
// 4 200 000 m must keep every digit.
std::string axis_value(double v, const std::vector<double>& ticks) {
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  const int decimals = std::clamp(-static_cast<int>(std::floor(std::log10(step) + 1e-9)), 0, 6);
  if (std::abs(v) < 1e-9 * step) v = 0.0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// The longest 1, 2 or 5 times a power of ten not above `at_most` (m): the scale bar's length.
double round_length(double at_most) {
  const double p = std::pow(10.0, std::floor(std::log10(at_most)));
  for (double k : {5.0, 2.0, 1.0})
    if (k * p <= at_most) return k * p;
  return p;
}

std::string three_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

struct Layout {
  PictureFrame frame;
  PictureMetrics m{};
  // With axes: the tick values (m) inside the blocks' extent, the world box they frame, the
  // row of the x values and of the x label and scale bar, and the y label's row.
  std::vector<double> x_ticks, y_ticks;
  double xmin = 0.0, xmax = 0.0, ymin = 0.0, ymax = 0.0;
  int x_values_y = 0;
  int x_label_y = 0;
  int y_label_y = 0;
  int title_y = 0;
  int legend_y = 0;
  LegendPlacement legend;
  int bar_y = 0;
};

Layout lay_out(const std::vector<PictureBlock>& blocks, const PictureOptions& o) {
  if (o.width_px < 64) throw std::invalid_argument("block picture: width_px must be at least 64");
  double xmin = std::numeric_limits<double>::infinity();
  double ymin = xmin;
  double xmax = -xmin;
  double ymax = -xmin;
  for (const PictureBlock& b : blocks)
    for (const Vec2& p : b.polygon) {
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        throw std::invalid_argument("block picture: a vertex is not finite");
      xmin = std::min(xmin, p.x());
      xmax = std::max(xmax, p.x());
      ymin = std::min(ymin, p.y());
      ymax = std::max(ymax, p.y());
    }
  if (!(xmax >= xmin)) throw std::invalid_argument("block picture: no blocks to draw");
  if (xmax == xmin && ymax == ymin) throw std::invalid_argument("block picture: the blocks have no extent");

  Layout L;
  L.m = picture_metrics(o.width_px);
  const PictureMetrics& m = L.m;
  int y = m.margin;
  if (!o.title.empty()) {
    L.title_y = y;
    y += m.line + m.gap;
  }

  // Axes: the round values inside the blocks' extent, about one per 200 px across and as
  // many per metre up; room on the left for the widest y value, a row above for "y (m)".
  L.xmin = xmin, L.xmax = xmax, L.ymin = ymin, L.ymax = ymax;
  int axis_left = 0;
  if (o.axes) {
    const int across = std::max(2, o.width_px / 200);
    const double aspect = xmax > xmin ? (ymax - ymin) / (xmax - xmin) : 1.0;
    L.x_ticks = ticks_within(nice_ticks(xmin, xmax, across), xmin, xmax);
    L.y_ticks = ticks_within(nice_ticks(ymin, ymax, std::clamp(static_cast<int>(std::lround(across * aspect)), 2, 3 * across)), ymin, ymax);
    for (double t : L.y_ticks) axis_left = std::max(axis_left, text_width(axis_value(t, L.y_ticks), m.text_scale));
    axis_left += 6 * m.text_scale;
    L.y_label_y = y;
    y += m.line;
  }

  // The blocks: as wide as the margins allow, unless that makes them taller than three
  // widths (a tall column), then as tall as that; centred across.
  const double plot_w = o.width_px - 2 * m.margin - axis_left;
  const double max_plot_h = 3.0 * o.width_px;
  const double inf = std::numeric_limits<double>::infinity();
  double scale = std::min(xmax > xmin ? plot_w / (xmax - xmin) : inf,
                          ymax > ymin ? max_plot_h / (ymax - ymin) : inf);
  const double drawn_w = scale * (xmax - xmin);
  L.frame.scale = scale;
  L.frame.offset_x = m.margin + axis_left + 0.5 * (plot_w - drawn_w) - scale * xmin;
  L.frame.offset_y = y + scale * ymax;
  // +1: the outline of the lowest edge sits on the pixel row just below its last filled row.
  y += static_cast<int>(std::ceil(scale * (ymax - ymin))) + 1;
  if (o.axes) {
    y += 6 * m.text_scale;  // the axis line 3 px below the blocks, ticks, a space
    L.x_values_y = y;
    y += m.line;
    L.x_label_y = y;
    y += m.line;
  }

  if (!o.legend.empty()) {
    y += m.gap;
    L.legend_y = y;
    L.legend = place_legend(o.legend, o.width_px - 2 * m.margin, m);
    y += L.legend.height;
  }
  if (o.colour_bar) {
    y += m.gap;
    L.bar_y = y;
    y += m.line + 3 * 7 * m.text_scale + 2 * m.text_scale + m.line;  // label, bar, tick labels
  }
  L.frame.width = o.width_px;
  L.frame.height = y + m.margin;
  return L;
}

void draw_colour_bar(Image& image, const ColourBar& bar, int y, const PictureOptions& o, const PictureMetrics& m) {
  const int s = m.text_scale;
  draw_text(image, m.margin, y, bar.label, s, o.text);
  y += m.line;
  const int x0 = m.margin;
  const int w = std::max(64, (o.width_px - 2 * m.margin) / 2);
  const int h = 3 * 7 * s;
  // Column i shows t = i / (w - 1): the end columns are exactly the colours of min and max.
  for (int i = 0; i < w; ++i)
    fill_rect(image, x0 + i, y, 1, h, sequential_colour(static_cast<double>(i) / (w - 1)));
  draw_rect(image, x0 - 1, y - 1, w + 2, h + 2, o.edge);  // around the bar, not on it
  y += h + 2 * s;
  const std::string lo = three_digits(bar.min);
  const std::string mid = three_digits(0.5 * (bar.min + bar.max));
  const std::string hi = three_digits(bar.max);
  draw_text(image, x0, y, lo, s, o.text);
  draw_text(image, x0 + (w - text_width(mid, s)) / 2, y, mid, s, o.text);
  draw_text(image, x0 + w - text_width(hi, s), y, hi, s, o.text);
}

// The axes along the left and bottom of the blocks' extent, 3 px off it so that they never
// cover a block; ticks outward with their values in metres; "y (m)" above, "x (m)" below
// centred; and a scale bar of a round length at the right of the x label's row.
void draw_axes(Image& image, const Layout& L, const PictureOptions& o) {
  const int s = L.m.text_scale;
  const PictureFrame& f = L.frame;
  const int left = static_cast<int>(std::floor(f.to_pixel({L.xmin, 0.0}).x())) - 3;
  const int right = static_cast<int>(std::ceil(f.to_pixel({L.xmax, 0.0}).x()));
  const int top = static_cast<int>(std::floor(f.to_pixel({0.0, L.ymax}).y()));
  const int bottom = static_cast<int>(std::ceil(f.to_pixel({0.0, L.ymin}).y())) + 3;
  fill_rect(image, left, top, 1, bottom - top + 1, o.text);
  fill_rect(image, left, bottom, right - left + 1, 1, o.text);
  for (double t : L.x_ticks) {
    const int x = static_cast<int>(std::floor(f.to_pixel({t, 0.0}).x()));
    fill_rect(image, x, bottom, 1, 3 * s, o.text);
    const std::string v = axis_value(t, L.x_ticks);
    draw_text(image, x - text_width(v, s) / 2, L.x_values_y, v, s, o.text);
  }
  for (double t : L.y_ticks) {
    const int y = static_cast<int>(std::floor(f.to_pixel({0.0, t}).y()));
    fill_rect(image, left - 3 * s, y, 3 * s, 1, o.text);
    const std::string v = axis_value(t, L.y_ticks);
    draw_text(image, left - 4 * s - text_width(v, s), y - 7 * s / 2, v, s, o.text);
  }
  draw_text(image, L.m.margin, L.y_label_y, "y (m)", s, o.text);
  const std::string x_label = "x (m)";
  draw_text(image, (left + right - text_width(x_label, s)) / 2, L.x_label_y, x_label, s, o.text);
  // The scale bar: at most a fifth of the extent across, 3 font pixels thick, ends marked.
  const double length = round_length(0.2 * std::max(L.xmax - L.xmin, L.ymax - L.ymin));
  const int w = std::max(1, static_cast<int>(std::lround(length * f.scale)));
  const int x1 = right, x0 = right - w;
  fill_rect(image, x0, L.x_label_y + 2 * s, w, 3 * s, o.text);
  fill_rect(image, x0, L.x_label_y, 1, 7 * s, o.text);
  fill_rect(image, x1 - 1, L.x_label_y, 1, 7 * s, o.text);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g m", length);
  draw_text(image, x0 - kGlyphAdvance * s - text_width(buf, s), L.x_label_y, buf, s, o.text);
}

// A 2-pixel shaft from `from` to `to` (pixels) and a head of two strokes at `to`, 30 degrees
// off the shaft, a third of the shaft long but 4 to 12 px. An arrow shorter than a pixel is
// a dot.
void draw_arrow(Image& image, const Vec2& from, const Vec2& to, Rgb colour) {
  const Vec2 d = to - from;
  const double length = d.norm();
  draw_line(image, from, to, colour);
  if (length < 1.0) return;
  const Vec2 along = d / length;
  const Vec2 across(-along.y(), along.x());
  // The second pixel of the shaft's width, on the side that keeps it a straight band.
  const Vec2 side = std::abs(along.x()) > std::abs(along.y()) ? Vec2(0.0, 1.0) : Vec2(1.0, 0.0);
  draw_line(image, from + side, to + side, colour);
  const double head = std::clamp(length / 3.0, 4.0, 12.0);
  const double c = std::cos(M_PI / 6.0), s = std::sin(M_PI / 6.0);
  for (const double sign : {1.0, -1.0}) {
    const Vec2 back = -head * (c * along + sign * s * across);
    draw_line(image, to, to + back, colour);
    draw_line(image, to + side, to + side + back, colour);
  }
}

}  // namespace

PictureFrame picture_frame(const std::vector<PictureBlock>& blocks, const PictureOptions& options) {
  return lay_out(blocks, options).frame;
}

Image draw_blocks(const std::vector<PictureBlock>& blocks, const PictureOptions& o) {
  const Layout L = lay_out(blocks, o);
  const PictureMetrics& m = L.m;
  Image image(L.frame.width, L.frame.height, o.background);

  if (!o.title.empty())
    draw_text(image, (o.width_px - text_width(o.title, m.text_scale)) / 2, L.title_y, o.title,
              m.text_scale, o.text);

  Polygon pixels;
  for (const PictureBlock& b : blocks) {
    pixels.clear();
    for (const Vec2& p : b.polygon) pixels.push_back(L.frame.to_pixel(p));
    fill_polygon(image, pixels, b.fill);
  }
  for (const PictureBlock& b : blocks) {
    const std::size_t n = b.polygon.size();
    for (std::size_t i = 0; i < n; ++i)
      draw_line(image, L.frame.to_pixel(b.polygon[i]), L.frame.to_pixel(b.polygon[(i + 1) % n]), o.edge);
  }
  // Marked outlines over every plain one, so that a neighbour's edge never cuts them.
  for (const PictureBlock& b : blocks) {
    if (!b.outline) continue;
    const std::size_t n = b.polygon.size();
    for (std::size_t i = 0; i < n; ++i)
      draw_thick_line(image, L.frame.to_pixel(b.polygon[i]), L.frame.to_pixel(b.polygon[(i + 1) % n]),
                      b.outline_width, *b.outline);
  }
  // Lines (bolts, force chains) over the blocks; 2 pixels wide by default, so that they read
  // over the outlines.
  for (const PictureLine& line : o.lines) {
    draw_thick_line(image, L.frame.to_pixel(line.from), L.frame.to_pixel(line.to), line.width_px, line.colour);
  }
  if (o.axes) draw_axes(image, L, o);

  const int label_scale = o.label_scale > 0 ? o.label_scale : std::max(1, m.text_scale - 1);
  for (const PictureLabel& label : o.labels) {
    const Vec2 c = L.frame.to_pixel(label.at);
    const int w = text_width(label.text, label_scale);
    const int h = text_height(label_scale);
    const int x = static_cast<int>(std::lround(c.x())) - w / 2;
    const int y = static_cast<int>(std::lround(c.y())) - h / 2;
    fill_rect(image, x - 1, y - 1, w + 2, h + 2, Rgb{255, 255, 255});
    draw_text(image, x, y, label.text, label_scale, label.colour);
  }
  // Arrows over the labels: an arrow starting at a labelled point stays whole.
  for (const PictureArrow& a : o.arrows) {
    draw_arrow(image, L.frame.to_pixel(a.from), L.frame.to_pixel(a.to), a.colour);
  }

  draw_legend(image, o.legend, L.legend, m.margin, L.legend_y, m, o.edge, o.text);
  if (o.colour_bar) draw_colour_bar(image, *o.colour_bar, L.bar_y, o, m);
  return image;
}

void write_block_picture(const std::string& path, const std::vector<PictureBlock>& blocks,
                         const PictureOptions& options) {
  write_png(path, draw_blocks(blocks, options));
}

}  // namespace dda
