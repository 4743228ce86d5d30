// The report's conclusion: which treatment is best by each measure the
// reproduction takes, and the plain statement of its headline finding, with the numbers
// read from this run's results (nothing in it is written by hand).
#pragma once

#include <string>

#include "report.hpp"

namespace dda::paper {

std::string conclusion_report(const Options& opt, const AllResults& r);

}  // namespace dda::paper
