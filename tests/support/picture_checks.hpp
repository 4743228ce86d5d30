// The picture tests' shared helpers (io/test_png_writer.cpp, test_raster.cpp,
// test_bitmap_font.cpp, test_block_picture.cpp): temporary files, a small stored-deflate
// PNG reader written here (independent of the writer's code, with reference CRC-32 and
// Adler-32 from their definitions), pixel counts, rectangles by their corners and the
// colours the tests paint with. In a namespace of their own: rectangle() here takes two
// corners, scene_builders.hpp's an origin and a size.
#pragma once

#include <unistd.h>

#include <catch2/catch.hpp>
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

// Reference Adler-32 from the definition, reducing after every byte in 64 bits.
inline std::uint32_t adler32_naive(const Bytes& data) {
  std::uint64_t a = 1;
  std::uint64_t b = 0;
  for (std::uint8_t x : data) {
    a = (a + x) % 65521;
    b = (b + a) % 65521;
  }
  return static_cast<std::uint32_t>((b << 16) | a);
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

// Inflates a zlib stream made of stored deflate blocks only (RFC 1950, RFC 1951 3.2.4),
// checking the header, each block's NLEN, that the last block is marked final, and the
// Adler-32 trailer.
inline Bytes inflate_stored(const Bytes& z) {
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
