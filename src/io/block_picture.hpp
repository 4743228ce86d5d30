// PNG pictures of blocks, drawn in C++ with no library: each block's polygon filled with its
// colour and outlined, under an optional title, above an optional categorical legend (e.g.
// material names) and an optional continuous colour bar (e.g. displacement). The caller
// chooses the colours (io/colour_maps helps); this file only lays out and rasterises.
//
// World coordinates are metres with y up; the picture keeps equal scales in x and y and fits
// the bounding box of all blocks between margins. Pure functions of plain data, except
// write_block_picture, which writes the file (io/png_writer).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/colour_maps.hpp"
#include "io/image.hpp"
#include "io/picture_layout.hpp"
#include "kinematics/types.hpp"

namespace dda {

struct PictureBlock {
  Polygon polygon;  // world coordinates (m); concave allowed, either orientation
  Rgb fill;
  // A marked block (one that moves in a mechanism): its outline in this colour and width
  // (px), drawn over all plain outlines; none keeps the picture's 1 px edge.
  std::optional<Rgb> outline = std::nullopt;
  double outline_width = 3.0;
};

// A horizontal bar of sequential_colour(t) for t from 0 (left) to 1 (right), labelled with
// `min` and `max` (3 significant digits) at its ends and `label` above it. The caller maps its
// values to colours with sequential_colour((v - min) / (max - min)).
struct ColourBar {
  std::string label;
  double min = 0.0;
  double max = 1.0;
};

// An arrow drawn over the blocks from `from` to `to` (world coordinates, m), 2 px wide with
// a head at `to`: a displacement or velocity, scaled by the caller to be seen.
struct PictureArrow {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  Rgb colour = {200, 0, 0};
};

// A straight line between two world points (a rock bolt, a force chain's link), drawn over
// the blocks.
struct PictureLine {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  Rgb colour = {230, 120, 0};  // orange: apart from the materials' and the arrows' colours
  double width_px = 2.0;
};

// A short text (a block number) centred on a world point, on a white box so it reads over
// any fill.
struct PictureLabel {
  Vec2 at = Vec2::Zero();
  std::string text;
  Rgb colour = {0, 0, 0};
};

struct PictureOptions {
  int width_px = 1200;  // image width; the height follows from the blocks' aspect ratio
  std::string title;    // drawn centred at the top; may be empty
  std::vector<LegendEntry> legend;      // drawn under the blocks; may be empty
  std::optional<ColourBar> colour_bar;  // drawn under the legend
  std::vector<PictureLine> lines;       // over the blocks, under the labels (bolts)
  std::vector<PictureLabel> labels;     // over the blocks; text at the title's scale - 1
  std::vector<PictureArrow> arrows;     // over the labels, in order
  int label_scale = 0;                  // font pixels per pixel of the labels; 0: title's - 1
  // Axes in metres along the left and bottom of the blocks' extent, with round tick values,
  // "x (m)" and "y (m)", and a scale bar of a round length.
  bool axes = false;
  Rgb edge = {40, 40, 40};              // block outlines, 1 px
  Rgb background = {255, 255, 255};
  Rgb text = {0, 0, 0};
};

// Where the blocks land: world point (x, y) is at pixel coordinates
// (offset_x + scale * x, offset_y - scale * y), pixel (i, j) covering [i, i+1) x [j, j+1).
struct PictureFrame {
  int width = 0;
  int height = 0;
  double scale = 0.0;  // pixels per metre
  double offset_x = 0.0;
  double offset_y = 0.0;
  Vec2 to_pixel(const Vec2& world) const {
    return {offset_x + scale * world.x(), offset_y - scale * world.y()};
  }
};

// The frame draw_blocks uses for these blocks and options. Throws std::invalid_argument when
// there are no blocks, a coordinate is not finite, all blocks lie on one point, or
// width_px < 64.
PictureFrame picture_frame(const std::vector<PictureBlock>& blocks, const PictureOptions& options);

// The picture in memory: options.width_px wide, picture_frame(...).height high.
Image draw_blocks(const std::vector<PictureBlock>& blocks, const PictureOptions& options);

// draw_blocks written as a PNG file. Throws std::runtime_error naming the path when the file
// cannot be written.
void write_block_picture(const std::string& path, const std::vector<PictureBlock>& blocks,
                         const PictureOptions& options);

}  // namespace dda
