// Output helpers shared by the verification programs (verification/paper,
// verification/constitutive): CSVs at full precision (for plots and re-checks), report
// numbers at a few significant digits.
#pragma once

#include <filesystem>
#include <string>

#include "whole_file.hpp"

namespace dda::verification {

// Opens `dir/name` for writing, as a WholeFile (it appears under its name when finished),
// and writes the header line; throws std::runtime_error naming the file when it cannot be
// opened.
WholeFile open_csv(const std::filesystem::path& dir, const std::string& name,
                   const std::string& header);

// Shortest round-trip form of a double (17 significant digits at most).
std::string full(double x);

// `digits` significant digits, scientific when small or large ("1.23e-05"); NaN as "-".
std::string significant(double x, int digits);

// Fixed with `decimals` decimals ("0.707107").
std::string fixed(double x, int decimals);

}  // namespace dda::verification
