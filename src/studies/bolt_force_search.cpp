#include "studies/bolt_force_search.hpp"

#include <cmath>
#include <optional>

#include "kinematics/polygon.hpp"

namespace dda {

Scene with_bolt_force(Scene scene, double force) {
  for (BoltSpec& b : scene.bolts) {
    b.pretension = force;
    b.yield_force = force;
  }
  return scene;
}

namespace {

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
  const std::optional<bool> at_largest = stands(largest);
  if (!at_largest) return out;
  if (!*at_largest) {
    out.message = "no bolt force up to the free blocks' weight (" + std::to_string(largest) +
                  " N/m each bolt) holds the slope at F = " + std::to_string(target_factor);
    out.failing_force = largest;
    return out;
  }
  double lo = 0.0, hi = largest;  // lo fails, hi stands
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
