#include "studies/factor_cross_check.hpp"

#include <cstdio>

namespace dda {
namespace {

std::string format(double x, const char* spec) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, x);
  return buf;
}

}  // namespace

FactorCrossCheck cross_check_factor(const FosResult& result, const std::vector<BlockBound>& single,
                                    const LimitAnalysisResult& la) {
  FactorCrossCheck c;
  if (!single.empty() && result.last_stable > single.front().factor) {
    c.warning = true;
    c.text = "stable trials above the smallest single-block bound F = " +
             format(single.front().factor, "%.4f") + " (block " +
             std::to_string(single.front().block) +
             "): a trial held a block its own strength cannot hold, so the factor is not "
             "trustworthy";
  } else if (la.found && result.last_stable > la.upper) {
    c.warning = true;
    c.text = "stable trials above the limit-analysis factor F = " + format(la.factor, "%.4f") +
             ", which associative friction makes an upper bound for rigid blocks";
  } else if (la.found && result.factor_of_safety < (1.0 - kAssociativeGapNoted) * la.factor) {
    c.text = "strength reduction lies " +
             format(100.0 * (1.0 - result.factor_of_safety / la.factor), "%.0f") +
             " % below the limit analysis: its joints slip without dilating, while the limit "
             "analysis's open at their friction angle as they slip, which resists mechanisms "
             "of blocks sliding past each other (columns toppling, groups shearing; "
             "docs/limit-analysis.md)";
  }
  return c;
}

}  // namespace dda
