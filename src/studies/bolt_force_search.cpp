#include "studies/bolt_force_search.hpp"

#include <cmath>
#include <optional>

#include "kinematics/polygon.hpp"

namespace dda {

Scene with_bolt_force(Scene scene, double force) {
  // No force: no bolts. A bar of zero capacity is not the same to the solvers: it enters
  // each step yielding, and a step that shortens it unloads it into its elastic branch, a
  // stiff spring that held the search's slope at F = 1.5 where it fails at 1.25 unbolted.
  if (force == 0.0) {
    scene.bolts.clear();
    return scene;
  }
  for (BoltSpec& b : scene.bolts) {
    b.pretension = force;
    b.yield_force = force;
  }
  return scene;
}

namespace {

// The first force tried above zero, as a share of the free blocks' weight.
constexpr double kFirstForceShare = 1e-3;

// The free blocks' weight, N/m: the largest bolt force searched.
double free_weight(const Scene& scene) {
  double weight = 0.0;
  for (const BlockSpec& b : scene.blocks) {
    if (b.fixed) continue;
    const Material& m = scene.materials[static_cast<std::size_t>(b.material)];
    weight += m.parameters.density * std::abs(signed_area(b.vertices)) * scene.gravity.norm();
  }
  return weight;
}

}  // namespace

BoltForceSearch find_bolt_force(const Scene& scene, const FosSettings& settings,
                                double target_factor, const StopQuery& stop) {
  BoltForceSearch out;
  out.target_factor = target_factor;
  // One trial at the target with every bolt holding `force`; nullopt when interrupted or
  // when its consolidation diverged (out.message says which).
  const auto stands = [&](double force) -> std::optional<bool> {
    const Scene s = with_bolt_force(scene, force);
    const Consolidation c = consolidate(s, settings.consolidation_factor, [&](const World&, const RunStats&) {
      return !(stop && stop());
    });
    if (c.stats.interrupted) {
      out.interrupted = true;
      return std::nullopt;
    }
    if (c.stats.diverged) {
      out.message = "the consolidation with bolts at " + std::to_string(force) +
                    " N/m diverged: " + c.stats.message;
      return std::nullopt;
    }
    const FosSettings resolved = resolve_fos_settings(c.world, settings, c.settling.relaxation_steps);
    const TrialResult t = run_trial(c.world, resolved, target_factor, stop);
    if (t.interrupted) {
      out.interrupted = true;
      return std::nullopt;
    }
    out.trials.push_back({force, t.stable, t.verdict, t.largest_displacement});
    return t.stable;
  };
  const double largest = free_weight(scene);
  const std::optional<bool> at_zero = stands(0.0);
  if (!at_zero) return out;
  if (*at_zero) {
    out.found = true;
    out.force = 0.0;
    return out;
  }
  // Up from a thousandth of the weight, doubling, to the first force that stands: a
  // pretension far beyond what the slope needs can itself move the blocks it joins (bolts
  // between free blocks at a million newtons a metre pushed them past the speed limit), so
  // the bracket is sought from below rather than from the largest force down.
  double lo = 0.0, hi = kFirstForceShare * largest;  // lo fails, hi is tried
  for (;;) {
    const std::optional<bool> s = stands(hi);
    if (!s) return out;
    if (*s) break;
    lo = hi;
    if (hi >= largest) {
      out.message = "no bolt force up to the free blocks' weight (" + std::to_string(largest) +
                    " N/m each bolt) holds the slope at F = " + std::to_string(target_factor) +
                    ": its mechanism there does not pull on the bolts enough (it passes behind "
                    "or beside them); longer bolts, or bolts where it moves, may";
      out.failing_force = lo;
      return out;
    }
    hi = std::min(2.0 * hi, largest);
  }
  while (hi - lo > kBoltForceTolerance * hi) {
    const double mid = 0.5 * (lo + hi);
    const std::optional<bool> s = stands(mid);
    if (!s) return out;
    (*s ? hi : lo) = mid;
  }
  out.found = true;
  out.force = hi;
  out.failing_force = lo;
  return out;
}

}  // namespace dda
