// Scanline polygon fill and Bresenham lines: short, exact rules about which pixels are
// painted, so that tests can count them.
#include "io/raster.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace dda {

void fill_polygon(Image& image, const Polygon& poly, Rgb colour) {
  const std::size_t n = poly.size();
  if (n < 3) return;
  double ymin = poly[0].y();
  double ymax = ymin;
  for (const Vec2& p : poly) {
    ymin = std::min(ymin, p.y());
    ymax = std::max(ymax, p.y());
  }
  // Rows whose centre j + 0.5 lies in [ymin, ymax), clipped to the image.
  const int row_first = std::max(0, static_cast<int>(std::ceil(ymin - 0.5)));
  const int row_last = std::min(image.height - 1, static_cast<int>(std::ceil(ymax - 0.5)) - 1);

  std::vector<double> crossings;
  crossings.reserve(8);
  for (int row = row_first; row <= row_last; ++row) {
    const double yc = row + 0.5;
    crossings.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& a = poly[i];
      const Vec2& b = poly[(i + 1) % n];
      // Half-open in y: an edge counts when yc is in [min(ya, yb), max(ya, yb)), so a vertex
      // on the scanline is counted once and horizontal edges never.
      if ((a.y() <= yc) != (b.y() <= yc))
        crossings.push_back(a.x() + (yc - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    }
    std::sort(crossings.begin(), crossings.end());
    // Even-odd: inside between crossings 0-1, 2-3, ...; pixel centres i + 0.5 in [xa, xb).
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
      const int first = std::max(0, static_cast<int>(std::ceil(crossings[k] - 0.5)));
      const int last = std::min(image.width - 1, static_cast<int>(std::ceil(crossings[k + 1] - 0.5)) - 1);
      for (int x = first; x <= last; ++x) image.set(x, row, colour);
    }
  }
}

void draw_line(Image& image, const Vec2& from, const Vec2& to, Rgb colour) {
  int x0 = static_cast<int>(std::floor(from.x()));
  int y0 = static_cast<int>(std::floor(from.y()));
  const int x1 = static_cast<int>(std::floor(to.x()));
  const int y1 = static_cast<int>(std::floor(to.y()));
  // Bresenham for all octants: err tracks dx*|y - y_line| - dy*|x - x_line| in integers.
  const int dx = std::abs(x1 - x0);
  const int dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1;
  const int sy = y0 < y1 ? 1 : -1;
  int err = dx + dy;
  while (true) {
    image.set(x0, y0, colour);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      x0 += sx;
    }
    if (e2 <= dx) {
      err += dx;
      y0 += sy;
    }
  }
}

void draw_thick_line(Image& image, const Vec2& from, const Vec2& to, double width, Rgb colour) {
  if (!(width > 1.0)) {
    draw_line(image, from, to, colour);
    return;
  }
  const double h = 0.5 * width;
  const Vec2 d = to - from;
  const double length = d.norm();
  if (length > 0.0) {
    const Vec2 across = Vec2(-d.y(), d.x()) * (h / length);
    fill_polygon(image, {from + across, to + across, to - across, from - across}, colour);
  }
  for (const Vec2& end : {from, to}) {
    fill_polygon(image, {end + Vec2(-h, -h), end + Vec2(h, -h), end + Vec2(h, h), end + Vec2(-h, h)}, colour);
  }
}

void fill_rect(Image& image, int x0, int y0, int w, int h, Rgb colour) {
  for (int y = std::max(0, y0); y < std::min(image.height, y0 + h); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x0 + w); ++x) image.set(x, y, colour);
}

void draw_rect(Image& image, int x0, int y0, int w, int h, Rgb colour) {
  if (w <= 0 || h <= 0) return;
  fill_rect(image, x0, y0, w, 1, colour);
  fill_rect(image, x0, y0 + h - 1, w, 1, colour);
  fill_rect(image, x0, y0, 1, h, colour);
  fill_rect(image, x0 + w - 1, y0, 1, h, colour);
}

}  // namespace dda

