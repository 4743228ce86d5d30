// io/png_writer: the checksums against their published check values, a written PNG decoded
// back by the reader of support/picture_checks.hpp (independent of the writer's code), bad
// input, and the picture that CMake's picture_png_python hands to Python's zlib.
#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/block_picture.hpp"
#include "io/colour_maps.hpp"
#include "io/png_writer.hpp"
#include "support/picture_checks.hpp"

using namespace dda;
using namespace dda::test::picture;
namespace fs = std::filesystem;

namespace {

Bytes bytes_of(const std::string& s) { return Bytes(s.begin(), s.end()); }

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
