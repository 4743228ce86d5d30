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

TEST_CASE("png: CRC-32 gives its standard check values", "[picture][png]") {
  // CRC-32/ISO-HDLC check value (the CRC used by PNG, zlib and gzip); empty input gives 0.
  CHECK(crc32(bytes_of("123456789")) == 0xCBF43926U);
  CHECK(crc32({}) == 0U);

  // Long inputs: the writer's table-driven CRC against the bitwise definition.
  const Bytes ones(100000, 0xFF);
  Bytes pattern(70001);
  for (std::size_t i = 0; i < pattern.size(); ++i) pattern[i] = static_cast<std::uint8_t>(i * 31 + (i >> 8));
  for (const Bytes* data : std::vector<const Bytes*>{&ones, &pattern}) {
    CHECK(crc32(*data) == crc32_bitwise(data->data(), data->size()));
  }
}

TEST_CASE("png: a written file reads back with its exact pixels", "[picture][png]") {
  // 150 x 200 RGB: 200 rows of 451 bytes = 90200 bytes of image data, every pixel different,
  // so deflate cannot shorten it much and codes it over several blocks.
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

  // A 1 x 1 image: 4 bytes of image data.
  Image dot(1, 1, {1, 2, 3});
  const Decoded one = decode_png(encode_png(dot));
  CHECK(one.pixels == Bytes{1, 2, 3});
}

TEST_CASE("png: a picture of 2000 blocks is deflated well under 1 MB", "[picture][png]") {
  // 2000 blocks in 8 colours over a 1600-pixel-wide picture: the size of a cut slope's or a
  // factor-of-safety search's picture, which stored uncompressed took 4.4-5.8 MB. The bound
  // is what users asked of a picture, 1 MB; measured 19 kB (flat colours deflate to runs).
  std::vector<PictureBlock> blocks;
  for (int i = 0; i < 80; ++i)
    for (int j = 0; j < 25; ++j)
      blocks.push_back({rectangle(i + 0.3 * (j % 2), j, i + 1 + 0.3 * (j % 2), j + 1), category_colour((i * 7 + j) % 8)});
  PictureOptions o;
  o.width_px = 1600;
  o.title = "2000 blocks";
  o.colour_bar = ColourBar{"u (m)", 0.0, 1.0};
  const Image image = draw_blocks(blocks, o);
  const Bytes png = encode_png(image);
  CHECK(png.size() < 1000000U);
  CHECK(png.size() * 10 < image.pixels.size());  // at least 10x below the raw pixels
  CHECK(decode_png(png).pixels == image.pixels);
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
