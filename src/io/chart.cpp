// Layout, top to bottom: margin, title, y label, plot area, x tick values, x label, legend,
// margin; left to right: margin, y tick values, plot area, margin. Drawn in layers: bands,
// grid, series, vertical lines, frame and ticks, text.
#include "io/chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

#include "io/bitmap_font.hpp"
#include "io/picture_layout.hpp"
#include "io/png_writer.hpp"
#include "io/raster.hpp"

namespace dda {
namespace {

constexpr Rgb kGrid{232, 232, 232};
constexpr Rgb kInk{0, 0, 0};
constexpr Rgb kFrameColour{60, 60, 60};

bool drawn(double x, double y, bool log_y) {
  return std::isfinite(x) && std::isfinite(y) && (!log_y || y > 0.0);
}

// The tick values as text: as many decimals as the step needs for round steps of ordinary
// size, otherwise three significant digits; decades on a log axis as 1e-05.
std::string tick_text(double v, double step, bool decade) {
  char buf[32];
  if (decade) {
    std::snprintf(buf, sizeof buf, "1e%+03d", static_cast<int>(std::lround(v)));
    return buf;
  }
  if (std::abs(v) < 1e-9 * step) v = 0.0;  // -0 and round-off next to zero
  const double big = std::max(std::abs(v), step);
  if (step >= 1e-4 && big < 1e6) {
    const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  } else {
    std::snprintf(buf, sizeof buf, "%.3g", v);
  }
  return buf;
}

std::vector<LegendEntry> legend_of(const ChartOptions& o) {
  std::vector<LegendEntry> legend;
  for (const ChartSeries& s : o.series)
    if (!s.label.empty()) legend.push_back({s.label, s.colour});
  for (const ChartBand& b : o.bands)
    if (!b.label.empty()) legend.push_back({b.label, b.colour});
  for (const ChartVerticalLine& l : o.vertical_lines)
    if (!l.label.empty()) legend.push_back({l.label, l.colour});
  return legend;
}

struct Layout {
  ChartFrame frame;
  PictureMetrics m{};
  int title_y = 0;
  int y_label_y = 0;
  int x_values_y = 0;
  int x_label_y = 0;
  int legend_y = 0;
  std::vector<LegendEntry> legend;
  LegendPlacement placement;
};

Layout lay_out(const ChartOptions& o) {
  if (o.width_px < 200 || o.height_px < 150)
    throw std::invalid_argument("chart: the picture must be at least 200 x 150 pixels");
  const double inf = std::numeric_limits<double>::infinity();
  double xlo = inf, xhi = -inf, ylo = inf, yhi = -inf;
  for (const ChartSeries& s : o.series) {
    if (s.x.size() != s.y.size())
      throw std::invalid_argument("chart: series '" + s.label + "' has " + std::to_string(s.x.size()) +
                                  " x values and " + std::to_string(s.y.size()) + " y values");
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!drawn(s.x[i], s.y[i], o.log_y)) continue;
      const double y = o.log_y ? std::log10(s.y[i]) : s.y[i];
      xlo = std::min(xlo, s.x[i]);
      xhi = std::max(xhi, s.x[i]);
      ylo = std::min(ylo, y);
      yhi = std::max(yhi, y);
    }
  }
  if (!(xhi >= xlo)) throw std::invalid_argument("chart: no finite point to draw");
  for (const ChartBand& b : o.bands)
    for (double x : {b.from, b.to})
      if (std::isfinite(x)) xlo = std::min(xlo, x), xhi = std::max(xhi, x);
  for (const ChartVerticalLine& l : o.vertical_lines)
    if (std::isfinite(l.x)) xlo = std::min(xlo, l.x), xhi = std::max(xhi, l.x);
  // Quantities of one sign that come near zero are read against zero.
  if (!o.log_y && ylo > 0.0 && ylo < 0.5 * yhi) ylo = 0.0;
  if (!o.log_y && yhi < 0.0 && yhi > 0.5 * ylo) yhi = 0.0;

  Layout L;
  ChartFrame& f = L.frame;
  f.log_y = o.log_y;
  f.x_ticks = nice_ticks(xlo, xhi, 8);
  if (o.log_y) {
    const double lo = std::floor(ylo), hi = std::max(std::ceil(yhi), lo + 1.0);
    for (double d = lo; d <= hi + 0.5; d += 1.0) f.y_ticks.push_back(d);
  } else {
    f.y_ticks = nice_ticks(ylo, yhi, 6);
  }
  f.xmin = f.x_ticks.front();
  f.xmax = f.x_ticks.back();
  f.ymin = f.y_ticks.front();
  f.ymax = f.y_ticks.back();
  // Markers are squares around their points: the axes then run over the data with 3 % of
  // room on every side (so that a marker at an end stays off the frame), the ticks inside.
  if (std::any_of(o.series.begin(), o.series.end(), [](const ChartSeries& c) { return c.markers; })) {
    const double dx = 0.03 * (xhi > xlo ? xhi - xlo : f.xmax - f.xmin);
    const double dy = 0.03 * (yhi > ylo ? yhi - ylo : f.ymax - f.ymin);
    f.xmin = xlo - dx, f.xmax = xhi + dx, f.ymin = ylo - dy, f.ymax = yhi + dy;
    f.x_ticks = ticks_within(std::move(f.x_ticks), f.xmin, f.xmax);
    f.y_ticks = ticks_within(std::move(f.y_ticks), f.ymin, f.ymax);
  }

  // Text a size larger than a block picture's of the same width: a chart is read from its
  // numbers (2 font pixels a pixel at 900-1349 px wide).
  L.m = picture_metrics(o.width_px);
  L.m.text_scale = std::clamp(o.width_px / 450, 1, 4);
  L.m.line = text_height(L.m.text_scale) + 3 * L.m.text_scale;
  const PictureMetrics& m = L.m;
  const int s = m.text_scale;
  int widest = 0;
  const double y_step = f.y_ticks.size() > 1 ? f.y_ticks[1] - f.y_ticks[0] : 1.0;
  for (double v : f.y_ticks) widest = std::max(widest, text_width(tick_text(v, y_step, o.log_y), s));
  L.legend = legend_of(o);
  L.placement = place_legend(L.legend, o.width_px - 2 * m.margin, m);

  int top = m.margin;
  if (!o.title.empty()) {
    L.title_y = top;
    top += m.line + m.gap;
  }
  if (!o.y_label.empty()) {
    L.y_label_y = top;
    top += m.line;
  }
  int bottom = o.height_px - m.margin;
  if (!L.legend.empty()) {
    bottom -= L.placement.height;
    L.legend_y = bottom;
    bottom -= m.gap;
  }
  if (!o.x_label.empty()) {
    bottom -= m.line;
    L.x_label_y = bottom;
  }
  bottom -= m.line;
  L.x_values_y = bottom + 2 * s;
  bottom -= 3 * s;  // tick marks
  f.left = m.margin + widest + 4 * s;
  f.top = top + text_height(s) / 2;  // the top tick value's text centred on the frame's top
  f.width = o.width_px - m.margin - f.left - text_width("0000", s) / 2;
  f.height = bottom - f.top;
  if (f.width < 50 || f.height < 50)
    throw std::invalid_argument("chart: too many labels for a picture of this size");
  return L;
}

void dashed_vertical(Image& image, int x, int y0, int y1, Rgb colour) {
  for (int y = y0; y <= y1; ++y)
    if ((y - y0) % 8 < 5) image.set(x, y, colour);
}

}  // namespace

Vec2 ChartFrame::to_pixel(double x, double y) const {
  const double v = log_y ? std::log10(y) : y;
  return {left + (x - xmin) / (xmax - xmin) * width, top + height - (v - ymin) / (ymax - ymin) * height};
}

std::vector<double> nice_ticks(double lo, double hi, int at_most) {
  if (!(std::isfinite(lo) && std::isfinite(hi)) || at_most < 2)
    throw std::invalid_argument("nice_ticks: needs finite ends and at_most >= 2");
  if (lo > hi) std::swap(lo, hi);
  if (lo == hi) {
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  const double magnitude = std::pow(10.0, std::floor(std::log10((hi - lo) / at_most)));
  double step = 10.0 * magnitude;
  for (double k : {1.0, 2.0, 5.0, 10.0}) {
    step = k * magnitude;
    if (std::ceil(hi / step - 1e-9) - std::floor(lo / step + 1e-9) <= at_most) break;
  }
  const double first = std::floor(lo / step + 1e-9), last = std::ceil(hi / step - 1e-9);
  std::vector<double> ticks;
  for (double k = first; k <= last + 0.5; k += 1.0) ticks.push_back(k * step);
  return ticks;
}

std::vector<double> ticks_within(std::vector<double> ticks, double lo, double hi) {
  // k * step carries round-off relative to the values, not to the range.
  const double slack = 1e-9 * std::max({hi - lo, std::abs(lo), std::abs(hi)});
  std::erase_if(ticks, [&](double t) { return t < lo - slack || t > hi + slack; });
  return ticks;
}

ChartFrame chart_frame(const ChartOptions& options) { return lay_out(options).frame; }

Image draw_chart(const ChartOptions& o) {
  const Layout L = lay_out(o);
  const ChartFrame& f = L.frame;
  const PictureMetrics& m = L.m;
  const int s = m.text_scale;
  Image image(o.width_px, o.height_px, Rgb{255, 255, 255});
  const int right = f.left + f.width, bottom = f.top + f.height;
  const auto px = [&](double x) { return static_cast<int>(std::lround(f.left + (x - f.xmin) / (f.xmax - f.xmin) * f.width)); };

  for (const ChartBand& b : o.bands) {
    const int x0 = std::clamp(px(std::min(b.from, b.to)), f.left, right);
    const int x1 = std::clamp(px(std::max(b.from, b.to)), f.left, right);
    fill_rect(image, x0, f.top, std::max(1, x1 - x0), f.height, b.colour);
  }
  for (double x : f.x_ticks) draw_line(image, {px(x) + 0.5, f.top + 0.5}, {px(x) + 0.5, bottom - 0.5}, kGrid);
  for (double v : f.y_ticks) {
    const double y = f.top + f.height - (v - f.ymin) / (f.ymax - f.ymin) * f.height;
    draw_line(image, {f.left + 0.5, y}, {right - 0.5, y}, kGrid);
  }

  for (const ChartSeries& series : o.series) {
    bool have_last = false;
    Vec2 last = Vec2::Zero();
    for (std::size_t i = 0; i < series.x.size(); ++i) {
      if (!drawn(series.x[i], series.y[i], o.log_y)) {
        have_last = false;  // a gap in the data is a gap in the line
        continue;
      }
      const Vec2 p = f.to_pixel(series.x[i], series.y[i]);
      if (have_last && series.line_width > 0.0) draw_thick_line(image, last, p, series.line_width, series.colour);
      last = p;
      have_last = true;
    }
    if (!series.markers) continue;
    const int half = std::max(3, static_cast<int>(2.0 * series.line_width));
    for (std::size_t i = 0; i < series.x.size(); ++i) {
      if (!drawn(series.x[i], series.y[i], o.log_y)) continue;
      const Vec2 p = f.to_pixel(series.x[i], series.y[i]);
      const int cx = static_cast<int>(std::floor(p.x())), cy = static_cast<int>(std::floor(p.y()));
      fill_rect(image, cx - half, cy - half, 2 * half + 1, 2 * half + 1, series.colour);
    }
  }
  for (const ChartVerticalLine& l : o.vertical_lines) {
    if (!std::isfinite(l.x)) continue;
    const int x = px(l.x);
    dashed_vertical(image, x, f.top, bottom - 1, l.colour);
    dashed_vertical(image, x + 1, f.top, bottom - 1, l.colour);
  }

  // Frame, ticks and their values.
  draw_rect(image, f.left - 1, f.top - 1, f.width + 2, f.height + 2, kFrameColour);
  const double x_step = f.x_ticks.size() > 1 ? f.x_ticks[1] - f.x_ticks[0] : 1.0;
  for (double x : f.x_ticks) {
    fill_rect(image, px(x), bottom, std::max(1, s / 2 + 1), 3 * s, kFrameColour);
    const std::string t = tick_text(x, x_step, false);
    draw_text(image, px(x) - text_width(t, s) / 2, L.x_values_y, t, s, kInk);
  }
  const double y_step = f.y_ticks.size() > 1 ? f.y_ticks[1] - f.y_ticks[0] : 1.0;
  for (double v : f.y_ticks) {
    const int y = static_cast<int>(std::lround(f.top + f.height - (v - f.ymin) / (f.ymax - f.ymin) * f.height));
    fill_rect(image, f.left - 3 * s, y, 3 * s, std::max(1, s / 2 + 1), kFrameColour);
    const std::string t = tick_text(v, y_step, o.log_y);
    draw_text(image, f.left - 4 * s - text_width(t, s), y - 7 * s / 2, t, s, kInk);
  }

  if (!o.title.empty())
    draw_text(image, (o.width_px - text_width(o.title, s)) / 2, L.title_y, o.title, s, kInk);
  if (!o.y_label.empty()) draw_text(image, m.margin, L.y_label_y, o.y_label, s, kInk);
  if (!o.x_label.empty())
    draw_text(image, f.left + (f.width - text_width(o.x_label, s)) / 2, L.x_label_y, o.x_label, s, kInk);
  draw_legend(image, L.legend, L.placement, m.margin, L.legend_y, m, kFrameColour, kInk);
  return image;
}

void write_chart(const std::string& path, const ChartOptions& options) {
  write_png(path, draw_chart(options));
}

}  // namespace dda
