// What the command line asks for, shared by every part of the reproduction.
#pragma once

#include <filesystem>

namespace dda::paper {

struct Options {
  std::filesystem::path out;  // every CSV and report.md go here
  bool smoke = false;         // a short run for CI: fewer steps and treatments
};

}  // namespace dda::paper
