// The strength-reduction factor read beside the bounds dda fos computes for the same slope:
// the smallest single-block bound (no slope's factor exceeds it) and the rigid-block limit
// analysis (associative friction: an upper bound where the mechanism dilates). A stable trial
// above either is a warning; a factor far below the limit analysis gets its reason.
// docs/factor-of-safety.md, docs/limit-analysis.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "studies/limit_analysis.hpp"
#include "studies/strength_reduction.hpp"

namespace dda {

// A strength-reduction factor this far (a share) below the limit analysis gets a note on
// why. 5 %: the textbook mechanisms of verification/slope lie within 0.6 % of each other,
// the toppling case 17 % apart.
inline constexpr double kAssociativeGapNoted = 0.05;

struct FactorCrossCheck {
  std::string text;      // empty: nothing to say
  bool warning = false;  // the factor is not trustworthy (else a note on a difference)
};

// `result` must have found a factor. `single` sorted smallest first (single_block_bounds);
// `la` may be not computed or not found.
FactorCrossCheck cross_check_factor(const FosResult& result, const std::vector<BlockBound>& single,
                                    const LimitAnalysisResult& la);

// Static trials against dynamic ones (`dda fos --dynamic-check`): dynamic trials (dynamic
// coefficient 1) at (1 - a) F and (1 + a) F, F the static factor, a = kDynamicAgreement. The
// dynamic factor lies within a share a of the static one when the first stands and the second
// fails; otherwise the text says which way it lies and why.
inline constexpr double kDynamicAgreement = 0.05;

struct DynamicCheck {
  bool computed = false;
  std::vector<TrialResult> trials;  // at (1 - a) F, then at (1 + a) F
  bool agrees = false;
  std::string text;
};

// The factors the dynamic trials run at, for the static factor F.
std::vector<double> dynamic_check_factors(double factor_of_safety);

// `result` must have found a factor; `dynamic` holds the dynamic trials at
// dynamic_check_factors(its factor), in that order.
DynamicCheck judge_dynamic_check(const FosResult& result, std::vector<TrialResult> dynamic);

}  // namespace dda
