// The largest (and smallest) values the readers accept, in SI units, so that nothing the step
// forms from them overflows or vanishes in double precision (docs/scene-format.md, "Limits").
// Each bound lies far beyond anything physical, so only a typo or a wrong unit meets it: a
// Young's modulus of 1e308 would make the "auto" penalty infinite, a time step of 1e-300
// would make the inertia term m/dt^2 overflow, and either would be met only at the first
// solve, with nan written into the history. Checked once, here, at the key that gives it.
#pragma once

#include <string>
#include <string_view>

#include "io/json_input.hpp"

namespace dda::input {

// Pa: moduli, strengths and stresses. 1000 times diamond's Young's modulus (1.05e12 Pa).
inline constexpr double kLargestStress = 1e15;
// Strain (-): a material point's strain targets; 1000 times a rock's failure strain of
// order 1, so stress = E x strain stays below 1e18 Pa.
inline constexpr double kLargestStrain = 1e3;
// N/m: the penalty. 20 times the "auto" penalty of the stiffest material allowed (50 E).
inline constexpr double kLargestPenalty = 1e18;
// kg/m^3: 44 times osmium's density, the densest element's (22 590 kg/m^3).
inline constexpr double kLargestDensity = 1e6;
// m/s and rad/s: initial velocities. 14 times the speed of a meteorite's impact (70 km/s).
inline constexpr double kLargestSpeed = 1e6;
// m/s^2: gravity and the ground's acceleration. 1000 times the largest geotechnical
// centrifuge's 1000 g.
inline constexpr double kLargestAcceleration = 1e6;
// N/m: point loads, the largest stress over a kilometre.
inline constexpr double kLargestForce = 1e18;
// N/m^3: the water's unit weight, the densest matter at the largest gravity.
inline constexpr double kLargestUnitWeight = kLargestDensity * kLargestAcceleration;
// m: coordinates (vertices, pins, loads, monitors, the phreatic line, a model's joints), at
// most 2.5 times the Earth's circumference: map coordinates (UTM northings below 1e7 m) pass.
// Larger coordinates were read and then failed at the first solve: a block reaching 1e10 m
// ("not positive definite" at step 1: its 6x6 matrices mix terms in 1, size and size^2),
// a phreatic line at 1e11 m (1e15 Pa on the joints, "not positive definite" at step 114) or
// at 1e9 m (energy created, step 114). And the smallest polygon, 1 nm across: between the
// two, squared lengths and the blocks' second moments (size^4 x density) stay inside double
// precision's normal range.
inline constexpr double kLargestCoordinate = 1e8;
inline constexpr double kSmallestPolygon = 1e-9;
// Poisson's ratio: at most 0.499 (the elastic matrix is singular at 0.5; lambda / mu =
// 2 nu / (1 - 2 nu) is 499 there). Measured on the default scene's octagon landing on its
// floor (energy gained at the impact, as a share of the scene's scale): 1.2e-5 to 1.7e-5
// from nu = 0.25 to 0.4995, 3.8e-5 at 0.4999, then about tenfold for each further 9 nearer
// 0.5: 2.8e-4 at 0.49999, 3.8e-3 at 0.499999, 2.7 % at 0.4999999 (the energy guard stops the
// run), 2666 % at 0.4999999999; a plastic column cuts 52 of 300 steps at 0.4999999999 and
// none up to 0.4999999. Undrained soil is modelled with 0.49 to 0.495.
inline constexpr double kLargestPoisson = 0.499;
// s: time steps, stage durations and the run's end time. The step loop itself gives up on
// a step cut below 1e-9 of its schedule; below this the inertia term m/dt^2 would pass
// 1e18 m and a run could not cover a second in 2^31 steps.
inline constexpr double kSmallestDuration = 1e-9;

// `value` (already read from `f`) if |value| <= largest; otherwise fails at `f`, naming the
// limit and `unit` ("Pa").
// `what` prefixes the value in the message ("element 1 ").
double within_limit(const Field& f, double value, double largest, std::string_view unit,
                    const std::string& what = "");

// Each component of a vector read from `f` (fails at `f`, naming the component).
template <class Vector>
Vector within_limit(const Field& f, const Vector& value, double largest, std::string_view unit) {
  for (int k = 0; k < value.size(); ++k) {
    within_limit(f, value[k], largest, unit, "element " + std::to_string(k) + " ");
  }
  return value;
}

// `value` if value >= smallest; otherwise fails at `f`.
double at_least(const Field& f, double value, double smallest, std::string_view unit);

}  // namespace dda::input
