// A tiny built-in bitmap font for labels on pictures: every printable ASCII character
// (32..126) as a 5 x 9 pixel glyph (7 rows above the baseline, 2 for descenders of g, j,
// p, q, y, comma and underscore), drawn at an integer scale. Characters outside that range
// are drawn as a hollow box.
#pragma once

#include <string_view>

#include "io/image.hpp"

namespace dda {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 9;   // rows 0..6 above the baseline, 7..8 below
inline constexpr int kGlyphAdvance = 6;  // glyph plus one blank column

// True when `c` has a glyph of its own (not the hollow-box fallback).
bool has_glyph(char c);

// Whether glyph `c` paints pixel (col, row) of its 5 x 9 cell (row 0 at the top).
bool glyph_pixel(char c, int col, int row);

// Width and height in pixels of `text` drawn at `scale` (one line; no wrapping).
int text_width(std::string_view text, int scale);
inline int text_height(int scale) { return kGlyphHeight * scale; }

// Draws `text` with the top-left corner of its first cell at pixel (x, y); each font pixel
// becomes a scale x scale square. Pixels outside the image are clipped.
void draw_text(Image& image, int x, int y, std::string_view text, int scale, Rgb colour);

}  // namespace dda
