#include "io/input_limits.hpp"

#include <cmath>

namespace dda::input {
namespace {

// " Pa", or nothing for a pure number.
std::string with_unit(double value, std::string_view unit) {
  std::string text = format_number(value);
  if (!unit.empty()) text.append(" ").append(unit);
  return text;
}

}  // namespace

double within_limit(const Field& f, double value, double largest, std::string_view unit,
                    const std::string& what) {
  if (std::abs(value) > largest) {
    f.fail(what + with_unit(value, unit) + " is beyond what this program computes with: at most " +
           with_unit(largest, unit) +
           " in magnitude, far beyond anything physical (a wrong unit or a typo? see "
           "docs/scene-format.md, \"Limits\")");
  }
  return value;
}

double at_least(const Field& f, double value, double smallest, std::string_view unit) {
  if (value < smallest) {
    f.fail(with_unit(value, unit) + " is shorter than this program computes with: at least " +
           with_unit(smallest, unit) + " (see docs/scene-format.md, \"Limits\")");
  }
  return value;
}

}  // namespace dda::input
