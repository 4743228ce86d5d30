// Checks shared by the tests of the two factor-of-safety searches (studies/test_strength_reduction.cpp,
// studies/test_speculative_search.cpp).
#pragma once

#include <catch2/catch.hpp>

#include "studies/strength_reduction.hpp"

namespace dda::test {

// A search with one job over a made-up threshold of 1.37, stopped before its fourth trial:
// F = 1 stood, 2 and 1.5 failed. It ends not found, with the bracket [1, 1.5] of the judged
// trials and the fourth trial kept in the list, interrupted.
inline void check_stopped_after_three_trials(const FosResult& r) {
  CHECK(r.interrupted);
  CHECK_FALSE(r.found);
  REQUIRE(r.has_bracket);
  CHECK(r.last_stable == 1.0);
  CHECK(r.first_failing == 1.5);
  REQUIRE(r.trials.size() == 4);
  CHECK(r.trials.back().interrupted);
  CHECK_THAT(r.message, Catch::Contains("after 3 judged trials"));
}

}  // namespace dda::test
