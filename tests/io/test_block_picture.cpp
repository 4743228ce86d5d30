// io/png_writer, io/raster, io/bitmap_font, io/colour_maps and io/block_picture: the
// checksums against their published check values, a written PNG decoded back by a small
// stored-deflate reader written here (independent of the writer's code), pixel counts of the
// rasteriser against exact areas, and the layout of block pictures.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "io/bitmap_font.hpp"
#include "io/block_picture.hpp"
#include "io/colour_maps.hpp"
#include "io/png_writer.hpp"
#include "io/raster.hpp"

using namespace dda;
namespace fs = std::filesystem;

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes bytes_of(const std::string& s) { return Bytes(s.begin(), s.end()); }

// A file path under the system temp dir, removed when the test ends.
struct TempFile {
  fs::path path;
  explicit TempFile(const std::string& tag) {
    static int counter = 0;
    path = fs::temp_directory_path() /
           ("dda_test_picture_" + tag + "_" + std::to_string(getpid()) + "_" +
            std::to_string(counter++) + ".png");
  }
  ~TempFile() {
    std::error_code ec;
    fs::remove(path, ec);
  }
};

Bytes read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Reference CRC-32, bit by bit from the definition (no table): reflected polynomial
// 0xEDB88320, initial value and final XOR all ones.
std::uint32_t crc32_bitwise(const std::uint8_t* p, std::size_t n) {
  std::uint32_t c = 0xFFFFFFFFU;
  for (std::size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320U & (0U - (c & 1U)));
  }
  return ~c;
}

// Reference Adler-32 from the definition, reducing after every byte in 64 bits.
std::uint32_t adler32_naive(const Bytes& data) {
  std::uint64_t a = 1;
  std::uint64_t b = 0;
  for (std::uint8_t x : data) {
    a = (a + x) % 65521;
    b = (b + a) % 65521;
  }
  return static_cast<std::uint32_t>((b << 16) | a);
}

std::uint32_t be32(const Bytes& d, std::size_t at) {
  return (std::uint32_t{d.at(at)} << 24) | (std::uint32_t{d.at(at + 1)} << 16) |
         (std::uint32_t{d.at(at + 2)} << 8) | std::uint32_t{d.at(at + 3)};
}

struct Chunk {
  std::string type;
  Bytes data;
};

// Splits a PNG file into chunks, checking the signature and every chunk's CRC.
std::vector<Chunk> read_chunks(const Bytes& file) {
  const Bytes signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  REQUIRE(file.size() >= 8);
  REQUIRE(Bytes(file.begin(), file.begin() + 8) == signature);
  std::vector<Chunk> chunks;
  std::size_t at = 8;
  while (at < file.size()) {
    REQUIRE(at + 12 <= file.size());
    const std::uint32_t length = be32(file, at);
    REQUIRE(at + 12 + length <= file.size());
    Chunk c;
    c.type.assign(file.begin() + static_cast<std::ptrdiff_t>(at + 4), file.begin() + static_cast<std::ptrdiff_t>(at + 8));
    c.data.assign(file.begin() + static_cast<std::ptrdiff_t>(at + 8), file.begin() + static_cast<std::ptrdiff_t>(at + 8 + length));
    CHECK(be32(file, at + 8 + length) == crc32_bitwise(file.data() + at + 4, 4 + length));
    chunks.push_back(std::move(c));
    at += 12 + length;
  }
  return chunks;
}

// Inflates a zlib stream made of stored deflate blocks only (RFC 1950, RFC 1951 3.2.4),
// checking the header, each block's NLEN, that the last block is marked final, and the
// Adler-32 trailer.
Bytes inflate_stored(const Bytes& z) {
  REQUIRE(z.size() >= 6);
  CHECK((z[0] & 0x0F) == 8);                // CM = deflate
  CHECK((z[0] >> 4) <= 7);                  // window at most 32 KiB
  CHECK((z[0] * 256 + z[1]) % 31 == 0);     // FCHECK
  CHECK((z[1] & 0x20) == 0);                // no preset dictionary
  Bytes out;
  std::size_t at = 2;
  bool final = false;
  int blocks = 0;
  while (!final) {
    REQUIRE(at + 5 <= z.size());
    final = (z[at] & 1) != 0;
    REQUIRE(((z[at] >> 1) & 3) == 0);  // BTYPE 00: stored
    const unsigned len = z[at + 1] | (z[at + 2] << 8);
    const unsigned nlen = z[at + 3] | (z[at + 4] << 8);
    REQUIRE((len ^ 0xFFFFU) == nlen);
    at += 5;
    REQUIRE(at + len <= z.size());
    out.insert(out.end(), z.begin() + static_cast<std::ptrdiff_t>(at), z.begin() + static_cast<std::ptrdiff_t>(at + len));
    at += len;
    ++blocks;
  }
  REQUIRE(at + 4 == z.size());  // nothing after the trailer
  CHECK(be32(z, at) == adler32_naive(out));
  return out;
}

struct Decoded {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  Bytes pixels;  // RGB, row-major
};

// Reads a PNG of 8-bit RGB written with filter type 0 on every row.
Decoded decode_png(const Bytes& file) {
  const std::vector<Chunk> chunks = read_chunks(file);
  REQUIRE(chunks.size() >= 3);
  REQUIRE(chunks.front().type == "IHDR");
  REQUIRE(chunks.back().type == "IEND");
  CHECK(chunks.back().data.empty());
  const Bytes& ihdr = chunks.front().data;
  REQUIRE(ihdr.size() == 13);
  Decoded d;
  d.width = be32(ihdr, 0);
  d.height = be32(ihdr, 4);
  CHECK(ihdr[8] == 8);   // bit depth
  CHECK(ihdr[9] == 2);   // colour type RGB
  CHECK(ihdr[10] == 0);  // compression: deflate
  CHECK(ihdr[11] == 0);  // filter method 0
  CHECK(ihdr[12] == 0);  // no interlace
  Bytes z;
  for (std::size_t i = 1; i + 1 < chunks.size(); ++i) {
    REQUIRE(chunks[i].type == "IDAT");
    z.insert(z.end(), chunks[i].data.begin(), chunks[i].data.end());
  }
  const Bytes raw = inflate_stored(z);
  const std::size_t row = std::size_t{d.width} * 3 + 1;
  REQUIRE(raw.size() == row * d.height);
  for (std::size_t y = 0; y < d.height; ++y) {
    CHECK(raw[y * row] == 0);  // filter type None
    d.pixels.insert(d.pixels.end(), raw.begin() + static_cast<std::ptrdiff_t>(y * row + 1),
                    raw.begin() + static_cast<std::ptrdiff_t>((y + 1) * row));
  }
  return d;
}

int count(const Image& img, Rgb c) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += img.at(x, y) == c;
  return n;
}

Polygon rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

const Rgb kWhite{255, 255, 255};
const Rgb kRed{200, 0, 0};
const Rgb kBlue{0, 0, 200};

}  // namespace

TEST_CASE("png: CRC-32 and Adler-32 give their standard check values", "[picture][png]") {
  // CRC-32/ISO-HDLC check value (the CRC used by PNG, zlib and gzip).
  CHECK(crc32(bytes_of("123456789")) == 0xCBF43926U);
  // Adler-32 of "Wikipedia", the worked example of the algorithm (a = 920, b = 4582).
  CHECK(adler32(bytes_of("Wikipedia")) == 0x11E60398U);
  // Empty input: CRC 0 and Adler-32 1 by definition.
  CHECK(crc32({}) == 0U);
  CHECK(adler32({}) == 1U);

  // Long inputs: the writer's table-driven CRC and its blocked Adler-32 reduction against the
  // definitions (bitwise CRC, Adler reduced after every byte); 100000 bytes of 0xFF cross
  // many of Adler's 5552-byte reduction runs at its worst case for overflow.
  const Bytes ones(100000, 0xFF);
  Bytes pattern(70001);
  for (std::size_t i = 0; i < pattern.size(); ++i) pattern[i] = static_cast<std::uint8_t>(i * 31 + (i >> 8));
  for (const Bytes* data : std::vector<const Bytes*>{&ones, &pattern}) {
    CHECK(crc32(*data) == crc32_bitwise(data->data(), data->size()));
    CHECK(adler32(*data) == adler32_naive(*data));
  }
}

TEST_CASE("png: a written file reads back with its exact pixels", "[picture][png]") {
  // 150 x 200 RGB: 200 rows of 451 bytes = 90200 bytes of image data, more than one stored
  // block (at most 65535 bytes), so the block split is exercised.
  Image img(150, 200, kWhite);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.set(x, y, {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y),
                     static_cast<std::uint8_t>((x * 7 + y * 13) & 0xFF)});
  TempFile file("readback");
  write_png(file.path.string(), img);
  const Bytes bytes = read_file(file.path);
  CHECK(bytes == encode_png(img));

  const Decoded d = decode_png(bytes);
  CHECK(d.width == 150U);
  CHECK(d.height == 200U);
  CHECK(d.pixels == img.pixels);

  // A 1 x 1 image: one stored block of 4 bytes.
  Image dot(1, 1, {1, 2, 3});
  const Decoded one = decode_png(encode_png(dot));
  CHECK(one.pixels == Bytes{1, 2, 3});
}

TEST_CASE("png: bad input and an unwritable path are reported", "[picture][png]") {
  CHECK_THROWS_AS(encode_png(Image{}), std::invalid_argument);
  Image wrong(4, 4, kWhite);
  wrong.pixels.pop_back();
  CHECK_THROWS_AS(encode_png(wrong), std::invalid_argument);

  const std::string path = (fs::temp_directory_path() / "dda_no_such_dir_for_png" / "x.png").string();
  fs::remove_all(fs::path(path).parent_path());
  CHECK_THROWS_AS(write_png(path, Image(2, 2, kWhite)), std::runtime_error);
  CHECK_THROWS_WITH(write_png(path, Image(2, 2, kWhite)), Catch::Matchers::Contains(path));
}

// When DDA_PICTURE_OUT names a file, writes a block picture there for the independent check
// by Python's zlib (CMake's test picture_png_python). Hidden: run only by that test.
TEST_CASE("png: picture for the independent decoder", "[.png_python]") {
  const char* out = std::getenv("DDA_PICTURE_OUT");
  REQUIRE(out != nullptr);
  std::vector<PictureBlock> blocks;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 10; ++j)
      blocks.push_back({rectangle(i, j, i + 1, j + 1), category_colour(i + j)});
  PictureOptions o;
  o.width_px = 900;
  o.title = "independent check";
  o.legend = {{"a", category_colour(0)}};
  o.colour_bar = ColourBar{"u (m)", 0.0, 1.0};
  write_block_picture(out, blocks, o);
}

TEST_CASE("raster: a polygon paints the pixels whose centres it contains", "[picture][raster]") {
  SECTION("axis-aligned squares paint exactly their area") {
    // Integer corners: [2, 12) x [3, 13) holds the centres of exactly 10 x 10 pixels.
    Image img(20, 20, kWhite);
    fill_polygon(img, rectangle(2, 3, 12, 13), kRed);
    CHECK(count(img, kRed) == 100);
    CHECK(img.at(2, 3) == kRed);
    CHECK(img.at(11, 12) == kRed);
    CHECK(img.at(12, 12) == kWhite);
    CHECK(img.at(11, 13) == kWhite);
    // Shifted by 0.3 px: centres 2.5 .. 11.5 are still the 10 inside [2.3, 12.3).
    Image shifted(20, 20, kWhite);
    fill_polygon(shifted, rectangle(2.3, 3.3, 12.3, 13.3), kRed);
    CHECK(count(shifted, kRed) == 100);
  }
  SECTION("a rotated square paints its area to within its boundary pixels") {
    // A square of side 40 turned by 30 degrees, centred in a 100 x 100 image: area 1600 px.
    // Only pixels cut by the boundary can be miscounted; their number is at most the
    // perimeter times sqrt(2) (a pixel's largest extent across a line) plus the corners,
    // 4 * 40 * 1.42 + 4 < 232.
    const double c = std::cos(std::numbers::pi / 6);
    const double s = std::sin(std::numbers::pi / 6);
    Polygon square;
    for (const auto& [u, v] : {std::pair{-20.0, -20.0}, {20.0, -20.0}, {20.0, 20.0}, {-20.0, 20.0}})
      square.push_back({50.0 + c * u - s * v, 50.0 + s * u + c * v});
    Image img(100, 100, kWhite);
    fill_polygon(img, square, kRed);
    CHECK(std::abs(count(img, kRed) - 1600) < 232);
  }
  SECTION("a concave L leaves its notch empty") {
    // L = [0, 20) x [0, 20) minus the quadrant [10, 20) x [0, 10) (pixel y down): 300 px.
    const Polygon ell = {{0, 0}, {10, 0}, {10, 10}, {20, 10}, {20, 20}, {0, 20}};
    Image img(20, 20, kWhite);
    fill_polygon(img, ell, kRed);
    CHECK(count(img, kRed) == 300);
    CHECK(img.at(15, 5) == kWhite);
    CHECK(img.at(5, 5) == kRed);
    CHECK(img.at(15, 15) == kRed);
  }
  SECTION("polygons sharing an edge paint disjoint pixels that tile their union") {
    // The square [0, 30)^2 cut along its diagonal: the two triangles paint 900 pixels
    // between them, none twice, whatever happens on the diagonal.
    const Polygon lower = {{0, 0}, {30, 0}, {30, 30}};
    const Polygon upper = {{0, 0}, {30, 30}, {0, 30}};
    Image a(30, 30, kWhite);
    Image b(30, 30, kWhite);
    fill_polygon(a, lower, kRed);
    fill_polygon(b, upper, kBlue);
    int both = 0;
    int either = 0;
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 30; ++x) {
        both += a.at(x, y) == kRed && b.at(x, y) == kBlue;
        either += a.at(x, y) == kRed || b.at(x, y) == kBlue;
      }
    CHECK(both == 0);
    CHECK(either == 900);
  }
  SECTION("drawing off the image is clipped") {
    Image img(10, 10, kWhite);
    fill_polygon(img, rectangle(-5, -5, 5, 15), kRed);
    CHECK(count(img, kRed) == 50);  // [0, 5) x [0, 10)
  }
}

TEST_CASE("raster: lines include both end pixels and step once per pixel", "[picture][raster]") {
  Image img(20, 20, kWhite);
  draw_line(img, {2.5, 4.5}, {12.5, 4.5}, kRed);  // horizontal: pixels 2..12 of row 4
  CHECK(count(img, kRed) == 11);
  CHECK(img.at(2, 4) == kRed);
  CHECK(img.at(12, 4) == kRed);
  Image diag(20, 20, kWhite);
  draw_line(diag, {15.2, 1.7}, {3.9, 18.1}, kRed);  // from pixel (15, 1) to (3, 18)
  // A Bresenham line paints one pixel per step along its major axis: 18 - 1 + 1 = 18.
  CHECK(count(diag, kRed) == 18);
  CHECK(diag.at(15, 1) == kRed);
  CHECK(diag.at(3, 18) == kRed);
}

TEST_CASE("font: every character labels need has a glyph", "[picture][font]") {
  const std::string needed =
      "0123456789abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ .,-+()/:=%_[]";
  for (char c : needed) {
    INFO("character '" << c << "'");
    CHECK(has_glyph(c));
  }
  CHECK_FALSE(has_glyph('\t'));
  CHECK(text_width("", 2) == 0);
  CHECK(text_width("abc", 2) == (3 * 6 - 1) * 2);  // 3 cells of 6 px, last spacing dropped

  // '-' is the single row 3 of five pixels: at scale 2, a 10 x 2 bar at (x, y + 6).
  Image img(20, 20, kWhite);
  draw_text(img, 4, 1, "-", 2, kRed);
  CHECK(count(img, kRed) == 20);
  CHECK(img.at(4, 7) == kRed);
  CHECK(img.at(13, 8) == kRed);
  CHECK(img.at(14, 7) == kWhite);
}

TEST_CASE("colour maps: tab10 categories and viridis anchors", "[picture][colour]") {
  // Matplotlib's tab10: #1f77b4 blue, #ff7f0e orange, #17becf cyan (index 9).
  CHECK(category_colour(0) == Rgb{0x1f, 0x77, 0xb4});
  CHECK(category_colour(1) == Rgb{0xff, 0x7f, 0x0e});
  CHECK(category_colour(9) == Rgb{0x17, 0xbe, 0xcf});
  CHECK(category_colour(10) == category_colour(0));
  CHECK(category_colour(-1) == category_colour(9));
  std::map<std::tuple<int, int, int>, int> distinct;
  for (int i = 0; i < 10; ++i) {
    const Rgb c = category_colour(i);
    ++distinct[{c.r, c.g, c.b}];
  }
  CHECK(distinct.size() == 10U);

  // Viridis: #440154 at 0, #21918c at 1/2, #fde725 at 1; clamped outside [0, 1].
  CHECK(sequential_colour(0.0) == Rgb{0x44, 0x01, 0x54});
  CHECK(sequential_colour(0.5) == Rgb{0x21, 0x91, 0x8c});
  CHECK(sequential_colour(1.0) == Rgb{0xfd, 0xe7, 0x25});
  CHECK(sequential_colour(-3.0) == sequential_colour(0.0));
  CHECK(sequential_colour(7.0) == sequential_colour(1.0));
  CHECK(sequential_colour(std::nan("")) == sequential_colour(0.0));
  // Half way between the anchors at 0 (68, 1, 84) and 1/4 (59, 82, 139): the means 63.5,
  // 41.5 and 111.5, within the 1/2 of rounding to 8 bits.
  const Rgb mid = sequential_colour(0.125);
  CHECK(std::abs(mid.r - 63.5) <= 0.5);
  CHECK(std::abs(mid.g - 41.5) <= 0.5);
  CHECK(std::abs(mid.b - 111.5) <= 0.5);
  // Viridis gets lighter throughout: the sum of the channels grows with t here.
  int last = -1;
  for (int i = 0; i <= 20; ++i) {
    const Rgb c = sequential_colour(i / 20.0);
    const int sum = c.r + c.g + c.b;
    CHECK(sum > last);
    last = sum;
  }
}

TEST_CASE("block picture: blocks land at their size, shape and colour", "[picture][blocks]") {
  PictureOptions o;
  o.width_px = 200;

  SECTION("a unit square fills its area in pixels") {
    const std::vector<PictureBlock> blocks = {{rectangle(0, 0, 1, 1), kRed}};
    const PictureFrame f = picture_frame(blocks, o);
    // Margins of max(8, 200 / 50) = 8 px each side: 184 px per metre.
    CHECK(f.scale == Approx(184.0).epsilon(1e-12));  // exact up to rounding of one division
    const Image img = draw_blocks(blocks, o);
    CHECK(img.width == 200);
    CHECK(img.height == f.height);
    CHECK(img.pixels.size() == 3U * 200U * static_cast<std::size_t>(f.height));
    // Fill plus outline covers the square's 184^2 px to within its boundary pixels: the
    // outline may sit on a pixel row or column just outside the filled ones, 4 * 185 at most.
    const double area = f.scale * f.scale;
    const int painted = count(img, kRed) + count(img, o.edge);
    CHECK(std::abs(painted - area) <= 4 * (f.scale + 1));
    // The interior keeps its fill: the outline takes at most one pixel ring of the filled ones.
    CHECK(count(img, kRed) >= (f.scale - 2) * (f.scale - 2));
    // The square's centre (0.5, 0.5) m is red.
    const Vec2 centre = f.to_pixel({0.5, 0.5});
    CHECK(img.at(static_cast<int>(centre.x()), static_cast<int>(centre.y())) == kRed);
  }

  SECTION("equal scales in x and y: a 2 m x 1 m block is twice as wide as tall") {
    const std::vector<PictureBlock> blocks = {{rectangle(10, 5, 12, 6), kRed}};
    const Image img = draw_blocks(blocks, o);
    int xmin = img.width, xmax = -1, ymin = img.height, ymax = -1;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        if (img.at(x, y) == kRed) {
          xmin = std::min(xmin, x);
          xmax = std::max(xmax, x);
          ymin = std::min(ymin, y);
          ymax = std::max(ymax, y);
        }
    const int w = xmax - xmin + 1;
    const int h = ymax - ymin + 1;
    // 2 m at 92 px per metre; the outline may cover one filled column.
    CHECK(std::abs(w - 184) <= 1);
    // Each extent may lose one pixel to the outline: w / h = 2 to within 2 px of w.
    CHECK(std::abs(w - 2 * h) <= 2);
  }

  SECTION("a concave L-shaped block leaves its notch unfilled") {
    // L = [0, 2] x [0, 2] minus the upper-right quadrant (1, 2] x (1, 2].
    const Polygon ell = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    const std::vector<PictureBlock> blocks = {{ell, kRed}};
    const PictureFrame f = picture_frame(blocks, o);
    const Image img = draw_blocks(blocks, o);
    const auto at = [&](double x, double y) {
      const Vec2 p = f.to_pixel({x, y});
      return img.at(static_cast<int>(p.x()), static_cast<int>(p.y()));
    };
    CHECK(at(1.5, 1.5) == o.background);
    CHECK(at(0.5, 1.5) == kRed);
    CHECK(at(1.5, 0.5) == kRed);
    CHECK(at(0.5, 0.5) == kRed);
    // Three quarters of the 2 m x 2 m box, 3 m^2 at 92 px per metre, within the boundary
    // pixels of its 8 m perimeter (8 * 92 + 6 corners).
    const int painted = count(img, kRed) + count(img, o.edge);
    CHECK(std::abs(painted - 3.0 * f.scale * f.scale) <= 8 * f.scale + 6);
  }

  SECTION("two adjacent blocks of different colours both appear, equally") {
    const std::vector<PictureBlock> blocks = {{rectangle(0, 0, 1, 1), kRed},
                                              {rectangle(1, 0, 2, 1), kBlue}};
    const PictureFrame f = picture_frame(blocks, o);
    const Image img = draw_blocks(blocks, o);
    const Vec2 left = f.to_pixel({0.5, 0.5});
    const Vec2 right = f.to_pixel({1.5, 0.5});
    CHECK(img.at(static_cast<int>(left.x()), static_cast<int>(left.y())) == kRed);
    CHECK(img.at(static_cast<int>(right.x()), static_cast<int>(right.y())) == kBlue);
    // Same size: the counts differ at most by the one outline column the shared edge or the
    // right edge takes from one of them (f.scale + 1 px).
    CHECK(std::abs(count(img, kRed) - count(img, kBlue)) <= f.scale + 1);
    CHECK(count(img, kRed) > 0.9 * f.scale * f.scale);  // each at least 90 % filled
  }
}

TEST_CASE("block picture: title, legend and colour bar are drawn, width as asked", "[picture][blocks]") {
  const std::vector<PictureBlock> blocks = {{rectangle(0, 0, 4, 1), kRed}};
  PictureOptions plain;
  plain.width_px = 777;
  PictureOptions full = plain;
  full.title = "Slope, t = 1.5 s";
  const Rgb legend_colour{1, 2, 3};  // used nowhere else
  full.legend = {{"rock", legend_colour}, {"clay (soft)", kBlue}};
  full.colour_bar = ColourBar{"displacement (m)", 0.0, 0.0125};

  const Image a = draw_blocks(blocks, plain);
  const Image b = draw_blocks(blocks, full);
  CHECK(a.width == 777);
  CHECK(b.width == 777);
  CHECK(b.height > a.height);  // the extras add rows, not width
  CHECK(count(a, plain.text) == 0);
  CHECK(count(b, full.text) > 0);
  // The legend's swatch: 7 px of cap height at text scale 777 / 600 = 1, less its outline.
  CHECK(count(b, legend_colour) == 5 * 5);
  // The colour bar shows the sequential map's first and last colours.
  CHECK(count(b, sequential_colour(0.0)) > 0);
  CHECK(count(b, sequential_colour(1.0)) > 0);
  // The blocks keep their scale: the title goes above, the rest below.
  CHECK(picture_frame(blocks, full).scale == picture_frame(blocks, plain).scale);

  CHECK_THROWS_AS(draw_blocks({}, plain), std::invalid_argument);
  CHECK_THROWS_AS(draw_blocks({{{{1, 1}, {1, 1}, {1, 1}}, kRed}}, plain), std::invalid_argument);
  CHECK_THROWS_AS(draw_blocks({{{{0, 0}, {std::nan(""), 1.0}, {1, 1}}, kRed}}, plain), std::invalid_argument);
  TempFile file("blocks");
  write_block_picture(file.path.string(), blocks, full);
  const Decoded d = decode_png(read_file(file.path));
  CHECK(d.width == 777U);
  CHECK(d.pixels == b.pixels);
}
