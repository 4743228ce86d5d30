// The command line the paper and constitutive verification programs share:
// PROGRAM --out DIR [--FLAG]... [--help]. Their usage text and flags are their own.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace dda::verification {

// A flag the program takes (e.g. {"--smoke", &opt.smoke}): set to true when given.
using Flag = std::pair<std::string_view, bool*>;

// Reads argv into `out` and the flags. Returns nothing when the program should go on, or its
// exit code: 0 after --help (usage on stdout), 2 for an unknown argument or a missing
// --out (the reason and the usage on stderr, each message naming `program`).
std::optional<int> parse_arguments(int argc, char** argv, std::string_view program,
                                   std::string_view usage, std::string& out,
                                   std::initializer_list<Flag> flags);

}  // namespace dda::verification
