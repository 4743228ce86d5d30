#include "studies/factor_cross_check.hpp"

#include <utility>

#include "common/printf_text.hpp"

namespace dda {

FactorCrossCheck cross_check_factor(const FosResult& result, const std::vector<BlockBound>& single,
                                    const LimitAnalysisResult& la) {
  FactorCrossCheck c;
  if (!single.empty() && result.last_stable > single.front().factor) {
    c.warning = true;
    c.text = "stable trials above the smallest single-block bound F = " +
             printf_text(single.front().factor, "%.4f") + " (block " +
             std::to_string(single.front().block) +
             "): a trial held a block its own strength cannot hold, so the factor is not "
             "trustworthy";
  } else if (la.found && result.last_stable > la.upper) {
    c.warning = true;
    c.text = "stable trials above the limit-analysis factor F = " + printf_text(la.factor, "%.4f") +
             ", which associative friction makes an upper bound for rigid blocks";
  } else if (la.found && result.factor_of_safety < (1.0 - kAssociativeGapNoted) * la.factor) {
    c.text = "strength reduction lies " +
             printf_text(100.0 * (1.0 - result.factor_of_safety / la.factor), "%.0f") +
             " % below the limit analysis: its joints slip without dilating, while the limit "
             "analysis's open at their friction angle as they slip, which resists mechanisms "
             "of blocks sliding past each other (columns toppling, groups shearing; "
             "docs/limit-analysis.md)";
  }
  return c;
}

std::vector<double> dynamic_check_factors(double factor_of_safety) {
  return {(1.0 - kDynamicAgreement) * factor_of_safety, (1.0 + kDynamicAgreement) * factor_of_safety};
}

DynamicCheck judge_dynamic_check(const FosResult& result, std::vector<TrialResult> dynamic) {
  DynamicCheck c;
  c.computed = true;
  c.trials = std::move(dynamic);
  const std::vector<double> at = dynamic_check_factors(result.factor_of_safety);
  const TrialResult* below = nullptr;
  const TrialResult* above = nullptr;
  for (const TrialResult& t : c.trials) {
    if (t.interrupted) continue;
    if (t.factor == at[0]) below = &t;
    if (t.factor == at[1]) above = &t;
  }
  if (below == nullptr || above == nullptr) {
    c.text = "the dynamic trials were not both judged";
    return c;
  }
  const std::string share = printf_text(100.0 * kDynamicAgreement, "%.0f") + " %";
  const std::string lo = printf_text(at[0], "%.4f"), hi = printf_text(at[1], "%.4f");
  if (below->stable && !above->stable) {
    c.agrees = true;
    c.text = "dynamic trials agree within " + share + ": stable at F = " + lo + ", failing at F = " + hi;
  } else if (!below->stable) {
    c.text = "the dynamic factor lies more than " + share + " below the static one (a dynamic "
             "trial fails at F = " + lo + "): when the strengths drop, the motion a dynamic "
             "trial keeps carries the blocks past the positions where a static trial, starting "
             "every step from rest, comes to rest (columns toppling, load passed on as contacts "
             "slip); the static factor is the strength-reduction limit";
  } else {
    c.text = "the dynamic factor lies more than " + share + " above the static one (a dynamic "
             "trial stands at F = " + hi + "): as the blocks move, the forces they share "
             "(statically indeterminate) are redistributed, and the dynamic trial finds an "
             "equilibrium the static one does not reach";
  }
  return c;
}

}  // namespace dda
