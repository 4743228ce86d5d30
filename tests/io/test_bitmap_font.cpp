// io/bitmap_font: every character the labels need has a glyph, drawn where text_width says.
#include <catch2/catch.hpp>

#include <string>

#include "io/bitmap_font.hpp"
#include "support/picture_checks.hpp"

using namespace dda;
using namespace dda::test::picture;

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
