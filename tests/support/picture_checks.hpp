// The picture tests' shared helpers (io/test_png_writer.cpp, test_raster.cpp,
// test_bitmap_font.cpp, test_block_picture.cpp): temporary files, a small PNG reader written here (independent of the writer's code: a reference CRC-32 from its
// definition, zlib's inflate, all five row filters), pixel counts, rectangles by their corners and the
// colours the tests paint with. In a namespace of their own: rectangle() here takes two
// corners, scene_builders.hpp's an origin and a size.
#pragma once

#include <unistd.h>

#include <catch2/catch.hpp>
#include <zlib.h>

#include <cstdlib>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "io/image.hpp"
#include "kinematics/types.hpp"

namespace dda::test::picture {

using Bytes = std::vector<std::uint8_t>;

// A file path under the system temp dir, removed when the test ends.
struct TempFile {
  std::filesystem::path path;
  explicit TempFile(const std::string& tag) {
    static int counter = 0;
    path = std::filesystem::temp_directory_path() /
           ("dda_test_picture_" + tag + "_" + std::to_string(getpid()) + "_" +
            std::to_string(counter++) + ".png");
  }
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
};

inline Bytes read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Reference CRC-32, bit by bit from the definition (no table): reflected polynomial
// 0xEDB88320, initial value and final XOR all ones.
inline std::uint32_t crc32_bitwise(const std::uint8_t* p, std::size_t n) {
  std::uint32_t c = 0xFFFFFFFFU;
  for (std::size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320U & (0U - (c & 1U)));
  }
  return ~c;
}

inline std::uint32_t be32(const Bytes& d, std::size_t at) {
  return (std::uint32_t{d.at(at)} << 24) | (std::uint32_t{d.at(at + 1)} << 16) |
         (std::uint32_t{d.at(at + 2)} << 8) | std::uint32_t{d.at(at + 3)};
}

struct Chunk {
  std::string type;
  Bytes data;
};

// Splits a PNG file into chunks, checking the signature and every chunk's CRC.
inline std::vector<Chunk> read_chunks(const Bytes& file) {
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

// Inflates a zlib stream (RFC 1950) with zlib's own inflate, after checking its header by
// hand; zlib checks the Adler-32 trailer, and nothing may follow it.
inline Bytes inflate_stream(const Bytes& z) {
  REQUIRE(z.size() >= 6);
  CHECK((z[0] & 0x0F) == 8);                // CM = deflate
  CHECK((z[0] >> 4) <= 7);                  // window at most 32 KiB
  CHECK((z[0] * 256 + z[1]) % 31 == 0);     // FCHECK
  CHECK((z[1] & 0x20) == 0);                // no preset dictionary
  z_stream s{};
  REQUIRE(inflateInit(&s) == Z_OK);
  Bytes out;
  std::uint8_t buffer[65536];
  s.next_in = const_cast<Bytef*>(z.data());
  s.avail_in = static_cast<uInt>(z.size());
  int rc = Z_OK;
  while (rc == Z_OK) {
    s.next_out = buffer;
    s.avail_out = sizeof buffer;
    rc = inflate(&s, Z_NO_FLUSH);
    out.insert(out.end(), buffer, buffer + (sizeof buffer - s.avail_out));
  }
  const std::size_t left = s.avail_in;
  inflateEnd(&s);
  REQUIRE(rc == Z_STREAM_END);
  REQUIRE(left == 0);  // nothing after the trailer
  return out;
}

// The Paeth predictor of PNG filter type 4 (PNG spec section 9.4).
inline int paeth(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

struct Decoded {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  Bytes pixels;  // RGB, row-major
};

// Reads a PNG of 8-bit RGB written with filter type 0 on every row.
inline Decoded decode_png(const Bytes& file) {
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
  const Bytes raw = inflate_stream(z);
  const std::size_t stride = std::size_t{d.width} * 3;
  const std::size_t row = stride + 1;
  REQUIRE(raw.size() == row * d.height);
  // Undoes whichever of the five filters (PNG spec section 9.2) each row was written with.
  d.pixels.assign(stride * d.height, 0);
  for (std::size_t y = 0; y < d.height; ++y) {
    const int filter = raw[y * row];
    REQUIRE(filter <= 4);
    for (std::size_t i = 0; i < stride; ++i) {
      const int a = i >= 3 ? d.pixels[y * stride + i - 3] : 0;
      const int b = y > 0 ? d.pixels[(y - 1) * stride + i] : 0;
      const int c = (i >= 3 && y > 0) ? d.pixels[(y - 1) * stride + i - 3] : 0;
      const int predicted = filter == 0 ? 0 : filter == 1 ? a : filter == 2 ? b
                          : filter == 3 ? (a + b) / 2 : paeth(a, b, c);
      d.pixels[y * stride + i] = static_cast<std::uint8_t>(raw[y * row + 1 + i] + predicted);
    }
  }
  return d;
}

inline int count(const Image& img, Rgb c) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += img.at(x, y) == c;
  return n;
}

inline Polygon rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

inline const Rgb kWhite{255, 255, 255};
inline const Rgb kRed{200, 0, 0};
inline const Rgb kBlue{0, 0, 200};

}  // namespace dda::test::picture
