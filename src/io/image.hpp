// A picture in memory: 8-bit RGB pixels, row-major from the top-left corner, three bytes per
// pixel. Plain data shared by the PNG writer (io/png_writer) and the rasteriser
// (io/raster, io/bitmap_font, io/block_picture).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dda {

struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 3 bytes: r, g, b of each pixel

  Image() = default;
  Image(int w, int h, Rgb background) : width(w), height(h) {
    pixels.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
    for (std::size_t i = 0; i < pixels.size(); i += 3) {
      pixels[i] = background.r;
      pixels[i + 1] = background.g;
      pixels[i + 2] = background.b;
    }
  }

  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }

  Rgb at(int x, int y) const {
    const std::size_t i = index(x, y);
    return {pixels[i], pixels[i + 1], pixels[i + 2]};
  }

  // Sets pixel (x, y); pixels outside the image are ignored, so drawing may run off its edge.
  void set(int x, int y, Rgb c) {
    if (!inside(x, y)) return;
    const std::size_t i = index(x, y);
    pixels[i] = c.r;
    pixels[i + 1] = c.g;
    pixels[i + 2] = c.b;
  }

 private:
  std::size_t index(int x, int y) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
            static_cast<std::size_t>(x)) * 3;
  }
};

}  // namespace dda
