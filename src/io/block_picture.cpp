// Layout, top to bottom: margin, title, blocks, legend, colour bar, margin. The blocks are
// filled first and outlined afterwards, so a shared edge is drawn once over both neighbours.
#include "io/block_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "io/bitmap_font.hpp"
#include "io/png_writer.hpp"
#include "io/raster.hpp"

namespace dda {
namespace {

// Sizes in pixels, all derived from the width so pictures look alike at any size.
struct Metrics {
  int margin;      // around everything
  int text_scale;  // font pixel size: 2 at 1200-1799 px wide
  int line;        // height of a line of text, with spacing
  int gap;         // between sections
};

Metrics metrics(int width) {
  Metrics m{};
  m.margin = std::max(8, width / 50);
  m.text_scale = std::clamp(width / 600, 1, 4);
  m.line = text_height(m.text_scale) + 3 * m.text_scale;
  m.gap = m.margin / 2;
  return m;
}

// Legend entries flow left to right and wrap; returns the top-left corner of each entry's
// swatch relative to the legend's top-left corner, and the legend's height.
struct LegendPlacement {
  std::vector<std::pair<int, int>> corners;
  int height = 0;
};

LegendPlacement place_legend(const std::vector<LegendEntry>& legend, int available, const Metrics& m) {
  LegendPlacement p;
  if (legend.empty()) return p;
  const int swatch = 7 * m.text_scale;  // the cap height
  const int spacing = 3 * kGlyphAdvance * m.text_scale;
  int x = 0;
  int y = 0;
  for (const LegendEntry& e : legend) {
    const int w = swatch + kGlyphAdvance * m.text_scale + text_width(e.label, m.text_scale);
    if (x > 0 && x + w > available) {
      x = 0;
      y += m.line;
    }
    p.corners.emplace_back(x, y);
    x += w + spacing;
  }
  p.height = y + m.line;
  return p;
}

std::string three_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

struct Layout {
  PictureFrame frame;
  Metrics m{};
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
  L.m = metrics(o.width_px);
  const Metrics& m = L.m;
  int y = m.margin;
  if (!o.title.empty()) {
    L.title_y = y;
    y += m.line + m.gap;
  }

  // The blocks: as wide as the margins allow, unless that makes them taller than three
  // widths (a tall column), then as tall as that; centred across.
  const double plot_w = o.width_px - 2 * m.margin;
  const double max_plot_h = 3.0 * o.width_px;
  const double inf = std::numeric_limits<double>::infinity();
  double scale = std::min(xmax > xmin ? plot_w / (xmax - xmin) : inf,
                          ymax > ymin ? max_plot_h / (ymax - ymin) : inf);
  const double drawn_w = scale * (xmax - xmin);
  L.frame.scale = scale;
  L.frame.offset_x = m.margin + 0.5 * (plot_w - drawn_w) - scale * xmin;
  L.frame.offset_y = y + scale * ymax;
  // +1: the outline of the lowest edge sits on the pixel row just below its last filled row.
  y += static_cast<int>(std::ceil(scale * (ymax - ymin))) + 1;

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

void draw_colour_bar(Image& image, const ColourBar& bar, int y, const PictureOptions& o, const Metrics& m) {
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
  const Metrics& m = L.m;
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
  // Lines (bolts) over the blocks, two pixels wide so that they read over the outlines.
  for (const PictureLine& line : o.lines) {
    const Vec2 from = L.frame.to_pixel(line.from), to = L.frame.to_pixel(line.to);
    draw_line(image, from, to, line.colour);
    draw_line(image, from + Vec2(0.0, 1.0), to + Vec2(0.0, 1.0), line.colour);
  }

  const int label_scale = std::max(1, m.text_scale - 1);
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

  const int s = m.text_scale;
  for (std::size_t i = 0; i < o.legend.size(); ++i) {
    const int x = m.margin + L.legend.corners[i].first;
    const int y = L.legend_y + L.legend.corners[i].second;
    const int swatch = 7 * s;
    fill_rect(image, x, y, swatch, swatch, o.legend[i].colour);
    draw_rect(image, x, y, swatch, swatch, o.edge);
    draw_text(image, x + swatch + kGlyphAdvance * s, y, o.legend[i].label, s, o.text);
  }
  if (o.colour_bar) draw_colour_bar(image, *o.colour_bar, L.bar_y, o, m);
  return image;
}

void write_block_picture(const std::string& path, const std::vector<PictureBlock>& blocks,
                         const PictureOptions& options) {
  write_png(path, draw_blocks(blocks, options));
}

}  // namespace dda
