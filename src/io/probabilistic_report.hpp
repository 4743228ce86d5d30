// The probabilistic part of `dda fos --samples`' report: report.json's "probabilistic"
// section, its part of report.md, and the histogram picture (docs/factor-of-safety.md,
// "Probabilistic factor of safety").
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "solver/random_strength_spec.hpp"
#include "studies/probabilistic_fos.hpp"

namespace dda {

nlohmann::json probabilistic_json(const ProbabilisticResult& result, const RandomStrengths& spec);

// Markdown: the probability of failure with its interval, the factor's statistics, the
// variables, and a table of the first 200 judged samples.
std::string probabilistic_markdown(const ProbabilisticResult& result, const RandomStrengths& spec);

// One line for the command line: "P(F < 1) = 0.31 (95 % Wilson interval 0.27 to 0.35) over
// 400 samples; F mean 1.08, standard deviation 0.12 over 398".
std::string probabilistic_line(const ProbabilisticResult& result);

// Searching: DIR/factors.png, a histogram of the samples' factors (a step line) with
// F = 1 and the mean marked. With verdicts: DIR/verdicts.png, histograms of the first
// variable's drawn values among stable and among failing samples. Returns the file name
// written, or "" when no sample was judged (nothing to draw).
std::string write_probabilistic_chart(const std::filesystem::path& dir,
                                      const ProbabilisticResult& result,
                                      const RandomStrengths& spec);

}  // namespace dda
