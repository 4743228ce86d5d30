// studies/factor_cross_check: what dda fos says beside its factor, on made-up brackets and
// bounds (the bounds' own computation: test_limit_analysis.cpp).
#include <catch2/catch.hpp>

#include "studies/factor_cross_check.hpp"

using namespace dda;

namespace {

FosResult found(double stable, double failing) {
  FosResult r;
  r.found = r.has_bracket = true;
  r.last_stable = stable;
  r.first_failing = failing;
  r.factor_of_safety = 0.5 * (stable + failing);
  return r;
}

LimitAnalysisResult analysis(double factor, double upper) {
  LimitAnalysisResult la;
  la.computed = la.found = true;
  la.factor = factor;
  la.upper = upper;
  return la;
}

}  // namespace

TEST_CASE("the factor beside its bounds: a warning above them, a note far below the limit "
          "analysis, nothing in between",
          "[fos][limit_analysis]") {
  const std::vector<BlockBound> single{{7, 1.20, 1.201}, {3, 1.5, 1.501}};
  SECTION("a stable trial above the smallest single-block bound") {
    const FactorCrossCheck c = cross_check_factor(found(1.21, 1.22), single, analysis(1.19, 1.191));
    CHECK(c.warning);
    CHECK_THAT(c.text, Catch::Contains("single-block bound F = 1.2000 (block 7)"));
  }
  SECTION("a stable trial above the limit analysis's inadmissible end") {
    const FactorCrossCheck c = cross_check_factor(found(1.195, 1.205), single, analysis(1.19, 1.191));
    CHECK(c.warning);
    CHECK_THAT(c.text, Catch::Contains("limit-analysis factor F = 1.1900"));
  }
  SECTION("within 5 % below the limit analysis: nothing") {
    // 1.135 is 4.6 % below 1.19.
    const FactorCrossCheck c = cross_check_factor(found(1.13, 1.14), single, analysis(1.19, 1.191));
    CHECK_FALSE(c.warning);
    CHECK(c.text.empty());
  }
  SECTION("more than 5 % below: the reason, with the gap in per cent") {
    // 0.5977 against 1.1933: 50 % below (the steep-jointed slope of verification/slope-cut).
    const FactorCrossCheck c =
        cross_check_factor(found(0.59375, 0.6016), single, analysis(1.1933, 1.1945));
    CHECK_FALSE(c.warning);
    CHECK_THAT(c.text, Catch::Contains("lies 50 % below the limit analysis"));
    CHECK_THAT(c.text, Catch::Contains("without dilating"));
  }
  SECTION("no limit analysis: only the single-block bound speaks") {
    LimitAnalysisResult none;
    CHECK(cross_check_factor(found(0.5, 0.6), {}, none).text.empty());
  }
}

TEST_CASE("dynamic trials at 0.95 F and 1.05 F: agreement, or which way the dynamic factor lies",
          "[fos]") {
  const FosResult r = found(1.09, 1.10);  // F = 1.095
  const std::vector<double> at = dynamic_check_factors(r.factor_of_safety);
  REQUIRE(at.size() == 2);
  CHECK(at[0] == Approx(0.95 * 1.095).epsilon(1e-12));
  CHECK(at[1] == Approx(1.05 * 1.095).epsilon(1e-12));
  const auto trial = [](double f, bool stable) {
    TrialResult t;
    t.factor = f;
    t.stable = stable;
    return t;
  };
  const DynamicCheck agree = judge_dynamic_check(r, {trial(at[0], true), trial(at[1], false)});
  CHECK(agree.computed);
  CHECK(agree.agrees);
  CHECK_THAT(agree.text, Catch::Contains("agree within 5 %"));
  const DynamicCheck lower = judge_dynamic_check(r, {trial(at[0], false), trial(at[1], false)});
  CHECK_FALSE(lower.agrees);
  CHECK_THAT(lower.text, Catch::Contains("more than 5 % below"));
  const DynamicCheck higher = judge_dynamic_check(r, {trial(at[0], true), trial(at[1], true)});
  CHECK_FALSE(higher.agrees);
  CHECK_THAT(higher.text, Catch::Contains("more than 5 % above"));
  // An interrupted trial has no verdict: nothing is concluded.
  TrialResult stopped = trial(at[1], false);
  stopped.interrupted = true;
  const DynamicCheck none = judge_dynamic_check(r, {trial(at[0], true), stopped});
  CHECK_FALSE(none.agrees);
  CHECK_THAT(none.text, Catch::Contains("not both judged"));
}
