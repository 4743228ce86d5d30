// The axial law of a rock bolt or cable (a force element, solver/elements/bolt_element.hpp):
// an elastic-perfectly plastic bar of axial stiffness k (N/m per metre of thickness) that
// yields at +-N_y, as the fully grouted or anchored bolts of slope practice are modelled in
// UDEC's and RocPlane's support (a force that grows with the bolt's extension up to its
// capacity, then stays there while it extends). Pure functions over plain numbers: a step's
// extension dl (m, from the step's increments) and the force at its start N0 (N/m, tension
// positive) give the force at its end. Over a step the force is taken at the step's end
// (backward Euler, as for pins and contacts), which loses (N1 - N0)^2 / 2k a step to the
// integration; what the bar yields is plastic work N1 dl_p.
#pragma once

#include <cmath>
#include <limits>

namespace dda {

enum class BoltMode : unsigned char {
  Elastic,               // N1 = N0 + k dl, within the capacity
  YieldingInTension,     // N1 = +N_y, the bar lengthening
  YieldingInCompression  // N1 = -N_y, the bar shortening
};

struct BoltLaw {
  double stiffness = 0.0;  // k, N/m per metre of thickness
  double yield_force = std::numeric_limits<double>::infinity();  // N_y, N/m
};

// The mode a step starts in: yielding when the force at its start is at the capacity.
inline BoltMode start_bolt_mode(const BoltLaw& law, double n0) {
  if (n0 >= law.yield_force) return BoltMode::YieldingInTension;
  if (n0 <= -law.yield_force) return BoltMode::YieldingInCompression;
  return BoltMode::Elastic;
}

// The force at the step's end in `mode` for the extension dl.
inline double bolt_force(const BoltLaw& law, BoltMode mode, double n0, double dl) {
  switch (mode) {
    case BoltMode::YieldingInTension: return law.yield_force;
    case BoltMode::YieldingInCompression: return -law.yield_force;
    case BoltMode::Elastic: break;
  }
  return n0 + law.stiffness * dl;
}

// The mode the extension dl asks for, from the mode it was solved in: an elastic bar whose
// force would pass its capacity yields; a yielding bar that the step unloads (shortens in
// tension, lengthens in compression) is elastic again. The two are complementary: a bar
// solved in the mode this returns for its own answer is consistent.
inline BoltMode follow_bolt_mode(const BoltLaw& law, BoltMode mode, double n0, double dl) {
  switch (mode) {
    case BoltMode::Elastic: {
      const double n1 = n0 + law.stiffness * dl;
      if (n1 > law.yield_force) return BoltMode::YieldingInTension;
      if (n1 < -law.yield_force) return BoltMode::YieldingInCompression;
      return BoltMode::Elastic;
    }
    case BoltMode::YieldingInTension: return dl < 0.0 ? BoltMode::Elastic : mode;
    case BoltMode::YieldingInCompression: return dl > 0.0 ? BoltMode::Elastic : mode;
  }
  return mode;
}

// What one step of the bar does with the energy its blocks put in, N1 dl: the rise of its
// spring's energy N^2 / 2k, the integration's loss (N1 - N0)^2 / 2k, and the plastic work
// N1 dl_p of the extension beyond the elastic one, dl_p = dl - (N1 - N0) / k. The three add
// up to N1 dl exactly.
struct BoltStepWork {
  double end_force = 0.0;          // N1, N/m
  double plastic_extension = 0.0;  // dl_p, m (signed)
  double stored_rise = 0.0;        // (N1^2 - N0^2) / 2k, J/m
  double integration_loss = 0.0;   // (N1 - N0)^2 / 2k, J/m
  double plastic_work = 0.0;       // N1 dl_p, J/m
};

inline BoltStepWork bolt_step_work(const BoltLaw& law, BoltMode mode, double n0, double dl) {
  BoltStepWork w;
  w.end_force = bolt_force(law, mode, n0, dl);
  const double k = law.stiffness;
  const double elastic = (w.end_force - n0) / k;
  w.plastic_extension = mode == BoltMode::Elastic ? 0.0 : dl - elastic;
  w.stored_rise = (w.end_force * w.end_force - n0 * n0) / (2.0 * k);
  w.integration_loss = (w.end_force - n0) * (w.end_force - n0) / (2.0 * k);
  w.plastic_work = w.end_force * w.plastic_extension;
  return w;
}

// The energy the bar's spring holds at force N: N^2 / 2k.
inline double bolt_stored_energy(const BoltLaw& law, double force) {
  return force * force / (2.0 * law.stiffness);
}

}  // namespace dda
