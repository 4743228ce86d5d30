#include "format.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace dda::verification {

WholeFile open_csv(const std::filesystem::path& dir, const std::string& name,
                   const std::string& header) {
  const std::filesystem::path path = dir / name;
  WholeFile out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out << header << '\n';
  return out;
}

std::string full(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string significant(double x, int digits) {
  if (std::isnan(x)) return "-";
  char buf[32];
  if (x == 0.0 || (std::abs(x) >= 1e-3 && std::abs(x) < 1e4)) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  } else {
    std::snprintf(buf, sizeof buf, "%.*e", digits - 1, x);
  }
  return buf;
}

std::string fixed(double x, int decimals) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

}  // namespace dda::verification
