#include "io/picture_layout.hpp"

#include <algorithm>

#include "io/bitmap_font.hpp"
#include "io/raster.hpp"

namespace dda {

PictureMetrics picture_metrics(int width) {
  PictureMetrics m{};
  m.margin = std::max(8, width / 50);
  m.text_scale = std::clamp(width / 600, 1, 4);
  m.line = text_height(m.text_scale) + 3 * m.text_scale;
  m.gap = m.margin / 2;
  return m;
}

LegendPlacement place_legend(const std::vector<LegendEntry>& legend, int available, const PictureMetrics& m) {
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

void draw_legend(Image& image, const std::vector<LegendEntry>& legend, const LegendPlacement& placement,
                 int x0, int y0, const PictureMetrics& m, Rgb edge, Rgb text) {
  const int s = m.text_scale;
  const int swatch = 7 * s;
  for (std::size_t i = 0; i < legend.size(); ++i) {
    const int x = x0 + placement.corners[i].first;
    const int y = y0 + placement.corners[i].second;
    fill_rect(image, x, y, swatch, swatch, legend[i].colour);
    draw_rect(image, x, y, swatch, swatch, edge);
    draw_text(image, x + swatch + kGlyphAdvance * s, y, legend[i].label, s, text);
  }
}

}  // namespace dda
