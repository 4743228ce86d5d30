// A number as printf writes it under a format of one conversion ("%.4f", "%.3g"): the text of
// report lines and picture titles.
#pragma once

#include <cstdio>
#include <string>

namespace dda {

inline std::string printf_text(double x, const char* spec) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, x);
  return buf;
}

}  // namespace dda
