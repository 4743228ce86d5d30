// The root of a scalar equation g(x) = 0 above a start point where g >= 0, by Newton steps
// kept inside a bracket (bisection when a step leaves it). The returns use it for their
// one nonlinear unknown (the plastic multiplier, or eps_p at the end of the step): with a
// piecewise-linear cohesion g is piecewise linear, so Newton lands on the root as soon as it
// is in the right segment, and the bracket stops it cycling between segments.
#pragma once

#include <cmath>
#include <limits>

namespace dda {

struct ScalarRoot {
  double x = 0.0;
  bool converged = false;
  int evaluations = 0;
};

// g(x, &dg) returns g and its derivative. g(x0) >= 0 is expected; the root sought is the
// first sign change above x0, found by growing a bracket from x0 in steps that start at
// `first_step` (> 0) and double. Converged when |g| <= g_tol, or when the bracket or a
// Newton step has shrunk below x_tol.
template <class G>
ScalarRoot find_root_above(const G& g, double x0, double first_step, double g_tol, double x_tol) {
  constexpr int kMaxEvaluations = 200;
  ScalarRoot r;
  double dg = 0.0;
  double gx = g(x0, &dg);
  ++r.evaluations;
  double x = x0;
  double lo = x0, hi = std::numeric_limits<double>::infinity();
  if (gx <= g_tol) {
    r.x = x0;
    r.converged = true;
    return r;
  }
  double step = first_step;
  while (r.evaluations < kMaxEvaluations) {
    // Newton from x when it points into the bracket; otherwise bisect, or grow the bracket.
    double next;
    const bool newton = dg < 0.0 && x - gx / dg > lo && x - gx / dg < hi;
    if (newton) {
      next = x - gx / dg;
    } else if (std::isfinite(hi)) {
      next = 0.5 * (lo + hi);
    } else {
      next = lo + step;
      step *= 2.0;
    }
    const double moved = std::abs(next - x);
    x = next;
    gx = g(x, &dg);
    ++r.evaluations;
    if (gx > 0.0) lo = x;
    if (gx < 0.0) hi = x;
    if (std::abs(gx) <= g_tol || (newton && moved <= x_tol) || hi - lo <= x_tol) {
      r.x = x;
      r.converged = true;
      return r;
    }
  }
  r.x = x;
  return r;
}

}  // namespace dda
