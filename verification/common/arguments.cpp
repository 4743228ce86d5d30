#include "arguments.hpp"

#include <iostream>

namespace dda::verification {

std::optional<int> parse_arguments(int argc, char** argv, std::string_view program,
                                   std::string_view usage, std::string& out,
                                   std::initializer_list<Flag> flags) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    bool known = false;
    for (const Flag& f : flags) {
      if (arg == f.first) {
        *f.second = true;
        known = true;
      }
    }
    if (known) continue;
    if (arg == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (arg == "--help" || arg == "-h") {
      std::cout << usage;
      return 0;
    } else {
      std::cerr << program << ": unexpected argument \"" << arg << "\"\n" << usage;
      return 2;
    }
  }
  if (out.empty()) {
    std::cerr << program << ": --out DIR is required\n" << usage;
    return 2;
  }
  return std::nullopt;
}

}  // namespace dda::verification
