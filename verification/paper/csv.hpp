// CSV and markdown helpers of the paper reproduction (verification/common/format.hpp).
#pragma once

#include <string>

#include "../common/format.hpp"

namespace dda::paper {

using verification::fixed;
using verification::full;
using verification::open_csv;
using verification::WholeFile;

// Three significant digits unless asked otherwise.
inline std::string sig(double x, int digits = 3) { return verification::significant(x, digits); }

}  // namespace dda::paper
