#include "studies/consolidation_bonds.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "solver/stages.hpp"
#include "studies/strength_reduction.hpp"

namespace dda {
namespace {

// Strengths multiplied by this hold every bond of a slope: a 1 kPa cohesion becomes 1 GPa,
// beyond any stress gravity puts in rock.
constexpr double kUnbreakable = 1e6;

// A joint that bonds (cohesion or tensile strength) made to hold in tension and in shear
// alike: both strengths become the larger of the two, times kUnbreakable. (A joint with no
// tensile strength would otherwise let go of every contact the slope pulls on, and these
// are the ones the check asks about.) A joint with neither stays frictional.
void make_unbreakable(JointMaterial& j) {
  const double strength = std::max(j.cohesion, j.tensile_strength);
  if (strength <= 0.0) return;
  j.cohesion = strength * kUnbreakable;
  j.tensile_strength = strength * kUnbreakable;
}

}  // namespace

double bond_demand(double normal_force, double shear_force, double length, const JointLaw& law) {
  const double inf = std::numeric_limits<double>::infinity();
  double demand = 0.0;
  if (normal_force < 0.0) {
    const double capacity = law.tensile_strength * length;
    demand = capacity > 0.0 ? -normal_force / capacity : inf;
  }
  if (shear_force != 0.0) {
    const double capacity = law.cohesion * length + law.tan_phi * std::max(0.0, normal_force);
    demand = std::max(demand, capacity > 0.0 ? std::abs(shear_force) / capacity : inf);
  }
  return demand;
}

BondCheck check_consolidation_bonds(const Scene& scene, double consolidation_factor,
                                    const std::vector<BrokenBond>& broken,
                                    const std::function<bool()>& stop) {
  const auto start = std::chrono::steady_clock::now();
  BondCheck out;
  Scene held = scene;
  for (JointMaterial& j : held.joint_materials) make_unbreakable(j);
  for (StageSpec& stage : held.stages) {
    for (StageJoint& j : stage.joint_materials) make_unbreakable(j.material);
  }
  const Consolidation elastic = consolidate(held, consolidation_factor, [&](const World&, const RunStats&) {
    return !(stop && stop());
  });
  out.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (elastic.stats.diverged || elastic.stats.interrupted) {
    out.reason = elastic.stats.diverged ? "the elastic consolidation diverged: " + elastic.stats.message
                                        : "stopped";
    return out;
  }
  // The real strengths, as the consolidation used them (the scene's joints divided by its
  // factor; a stage's replacement joints are not followed).
  std::vector<JointLaw> laws;
  for (const JointMaterial& j : scene.joint_materials) {
    laws.push_back(reduced_joint_law(joint_law_of(j), consolidation_factor));
  }
  const World& w = elastic.world;
  std::vector<double> demand(w.contacts.size(), 0.0);
  for (std::size_t i = 0; i < w.contacts.size(); ++i) {
    const Contact& c = w.contacts[i];
    if (!c.state.bonded) continue;
    // The state keeps the compression only; a bonded contact held open carries the
    // tension of its normal spring, p (gap - rest shift), as the open-close loop computes
    // it (solver/open_close_modes.cpp).
    const double spring_gap = c.gap - c.state.rest_shift;
    const double normal = spring_gap > 0.0 ? -w.penalty * spring_gap : c.state.normal_force;
    demand[i] = bond_demand(normal, c.iterate.shear_force, c.length,
                            law_at_stress(contact_joint_law(laws, c), c.state.normal_force, c.length));
    ++out.bonded_elastic;
    if (demand[i] > kOverstressed) ++out.overstressed_elastic;
  }
  // A broken bond is the elastic contact of the same two blocks (vertex and edge) whose
  // vertex lies nearest the place it broke.
  for (const BrokenBond& b : broken) {
    ++out.broken;
    double nearest = std::numeric_limits<double>::infinity();
    double d = 0.0;
    for (std::size_t i = 0; i < w.contacts.size(); ++i) {
      const Contact& c = w.contacts[i];
      if (c.key.vertex_block != b.vertex_block || c.key.edge_block != b.edge_block) continue;
      const double r = (c.vertex - b.at).norm();
      if (r < nearest) {
        nearest = r;
        d = demand[i];
      }
    }
    if (d > kOverstressed) {
      ++out.explained;
    } else {
      out.unexplained.push_back({b, d});
    }
  }
  out.computed = true;
  return out;
}

}  // namespace dda
