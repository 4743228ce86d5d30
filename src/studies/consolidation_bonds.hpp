// Which of the bonds a consolidation broke an elastic solution of the slope also breaks.
// The reference is the same consolidation (same stages, dt, penalty) with every bond made
// unbreakable: its joints then act as elastic springs that hold in tension and in shear, and
// at its end each bonded contact's demand on the real strength is read off,
//   max( tension / (tensile strength x length), |shear| / (cohesion x length + tan(phi) N) ).
// A broken bond whose contact the elastic solution loads beyond its strength (demand > 1) is
// explained by the slope's own stresses; one it does not was broken by the consolidation's
// motion (gravity arriving too fast, springs ringing) or progressively, after its
// neighbours broke. docs/factor-of-safety.md, section 1.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "contact/joint_law.hpp"

#include "solver/run_stats.hpp"
#include "solver/scene.hpp"

namespace dda {

struct UnexplainedBond {
  BrokenBond bond;
  double elastic_demand = 0.0;  // < 1; 0 when the elastic solution has no such contact
};

struct BondCheck {
  bool computed = false;
  std::string reason;            // why not (the elastic consolidation diverged or stopped)
  long broken = 0;               // the bonds the consolidation broke that the check saw
  long explained = 0;            // of them, overstressed in the elastic solution
  long bonded_elastic = 0;       // bonded contacts at the end of the elastic consolidation
  long overstressed_elastic = 0; // of them, loaded beyond their strength
  std::vector<UnexplainedBond> unexplained;  // the rest of `broken`, in the order broken
  double wall_time_s = 0.0;
};

// A demand above this counts as overstressed: 1 less the open-close loop's tolerance on
// the friction test (a contact at its strength to within rounding is at it).
inline constexpr double kOverstressed = 1.0 - 1e-6;

// The demand of one bonded contact on its joint's strength (see above); 0 for a contact
// carrying nothing. `length` the contact's share of the joint (m).
double bond_demand(double normal_force, double shear_force, double length, const JointLaw& law);

// `scene` consolidated at `consolidation_factor` broke `broken` (RunStats::broken_bonds, the
// first 1000 of them). Runs the elastic reference and compares. `stop` (may be empty) is
// asked after each step; true stops it (computed false).
BondCheck check_consolidation_bonds(const Scene& scene, double consolidation_factor,
                                    const std::vector<BrokenBond>& broken,
                                    const std::function<bool()>& stop = {});

}  // namespace dda
