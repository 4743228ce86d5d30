// What the command line asks for, shared by every part of the reproduction.
#pragma once

#include <filesystem>

namespace dda::paper {

struct Options {
  std::filesystem::path out;  // every CSV and report.md go here
  bool smoke = false;         // a short run for CI: fewer steps and treatments
  bool closed_form_only = false;  // only the incline's and the plastic specimen's sweeps
};

}  // namespace dda::paper
