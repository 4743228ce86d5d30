// Drawing primitives on an Image, in pixel coordinates: x to the right, y down, pixel (i, j)
// covering the square [i, i+1) x [j, j+1), so its centre is (i + 0.5, j + 0.5). Anything
// falling outside the image is clipped. Pure functions over plain data.
#pragma once

#include "io/image.hpp"
#include "kinematics/types.hpp"

namespace dda {

// Fills every pixel whose centre lies inside the polygon (even-odd rule, scanline at pixel
// centres). Each edge is half-open (a centre exactly on the boundary is in on the side of
// smaller x, and of smaller y for a vertex), so two polygons sharing an edge never both paint
// a pixel and an axis-aligned square [a, a+n) x [b, b+n) with integer corners paints n * n. The polygon may be concave and
// its orientation does not matter.
void fill_polygon(Image& image, const Polygon& pixel_polygon, Rgb colour);

// A 1-pixel line between the pixels holding the two points (Bresenham), both ends included.
void draw_line(Image& image, const Vec2& from, const Vec2& to, Rgb colour);

// A line `width` pixels wide (at least 1): the rectangle of that width around the segment,
// filled as a polygon, with a square of that width over each end so that joined segments
// (a polyline) leave no notch. Width 1 or less is draw_line.
void draw_thick_line(Image& image, const Vec2& from, const Vec2& to, double width, Rgb colour);

// Fills the pixels x in [x0, x0 + w), y in [y0, y0 + h).
void fill_rect(Image& image, int x0, int y0, int w, int h, Rgb colour);

// The outline of that same rectangle, 1 pixel wide, inside it.
void draw_rect(Image& image, int x0, int y0, int w, int h, Rgb colour);

}  // namespace dda
