// What the block pictures (io/block_picture) and the charts (io/chart) lay out alike: sizes
// that follow the picture's width, and a legend of colour swatches and labels that flows
// left to right and wraps.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "io/image.hpp"

namespace dda {

// Sizes in pixels, all derived from the width so pictures look alike at any size.
struct PictureMetrics {
  int margin;      // around everything
  int text_scale;  // font pixel size: 2 at 1200-1799 px wide
  int line;        // height of a line of text, with spacing
  int gap;         // between sections
};

PictureMetrics picture_metrics(int width);

struct LegendEntry {
  std::string label;
  Rgb colour;
};

// Where each entry's swatch goes, relative to the legend's top-left corner, and the legend's
// height, for entries flowing across `available` pixels.
struct LegendPlacement {
  std::vector<std::pair<int, int>> corners;
  int height = 0;
};

LegendPlacement place_legend(const std::vector<LegendEntry>& legend, int available, const PictureMetrics& m);

// Draws the legend placed by place_legend with its top-left corner at (x, y): a swatch with
// an outline of colour `edge`, then the label in colour `text`.
void draw_legend(Image& image, const std::vector<LegendEntry>& legend, const LegendPlacement& placement,
                 int x, int y, const PictureMetrics& m, Rgb edge, Rgb text);

}  // namespace dda
