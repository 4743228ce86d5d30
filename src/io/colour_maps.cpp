// Palette values are matplotlib's (matplotlib/_cm.py "tab10"; _cm_listed.py "viridis"),
// rounded to 8 bits.
#include "io/colour_maps.hpp"

#include <array>
#include <algorithm>
#include <cmath>

namespace dda {

Rgb category_colour(int index) {
  static constexpr std::array<Rgb, 10> kTab10 = {{
      {31, 119, 180},   // blue
      {255, 127, 14},   // orange
      {44, 160, 44},    // green
      {214, 39, 40},    // red
      {148, 103, 189},  // purple
      {140, 86, 75},    // brown
      {227, 119, 194},  // pink
      {127, 127, 127},  // grey
      {188, 189, 34},   // olive
      {23, 190, 207},   // cyan
  }};
  const int n = static_cast<int>(kTab10.size());
  return kTab10[static_cast<std::size_t>(((index % n) + n) % n)];
}

Rgb sequential_colour(double t) {
  static constexpr std::array<Rgb, 5> kViridis = {{
      {68, 1, 84},     // t = 0
      {59, 82, 139},   // t = 0.25
      {33, 145, 140},  // t = 0.5
      {94, 201, 98},   // t = 0.75
      {253, 231, 37},  // t = 1
  }};
  if (!(t > 0.0)) t = 0.0;  // also NaN
  if (t > 1.0) t = 1.0;
  const double u = t * static_cast<double>(kViridis.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(u), kViridis.size() - 2);
  const double f = u - static_cast<double>(i);
  const auto mix = [f](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::lround(a + f * (b - a)));
  };
  const Rgb& a = kViridis[i];
  const Rgb& b = kViridis[i + 1];
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

}  // namespace dda
