// Drawing the scene's random strengths (solver/random_strength_spec.hpp) for `dda fos
// --samples`, and putting a sample's values into a consolidated world
// (docs/factor-of-safety.md, "Probabilistic factor of safety").
//
// Reproducibility: sample k's values come from a generator seeded by (seed, k) alone, so
// they are the same whatever order samples are drawn in and however many threads draw them.
// Only fully specified algorithms are used: std::seed_seq and std::mt19937_64 (their output
// is fixed by the standard), uniforms from the generator's top 53 bits, normals by
// Box-Muller. std::normal_distribution and std::uniform_real_distribution are avoided: their
// algorithms are left to the library, so the same seed could give other values elsewhere.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "solver/random_strength_spec.hpp"
#include "solver/scene.hpp"
#include "solver/world.hpp"

namespace dda {

// The standard normal distribution function Phi(x) = erfc(-x / sqrt 2) / 2.
double standard_normal_cdf(double x);

// The generator of sample `index` under `seed`.
std::mt19937_64 sample_generator(std::uint64_t seed, std::uint64_t index);
// A uniform number in the open interval (0, 1): (top 53 bits + 1/2) / 2^53.
double open_uniform(std::mt19937_64& gen);
// A standard normal number by Box-Muller, sqrt(-2 ln u1) cos(2 pi u2) (Box and Muller
// 1958), from two uniforms; the sine half is not kept, so every draw takes two uniforms.
double standard_normal(std::mt19937_64& gen);

// The parameters of the normal distribution of ln X for a lognormal X of mean m and standard
// deviation s: sigma^2 = ln(1 + (s/m)^2), mu = ln m - sigma^2 / 2 (m > 0).
struct LogNormalParameters {
  double mu = 0.0;
  double sigma = 0.0;
};
LogNormalParameters lognormal_parameters(double mean, double standard_deviation);

// The variable's value at the standard normal z: mean + s z, or exp(mu + sigma z).
double strength_at(const RandomStrength& v, double z);
// P(lo <= X <= hi) for the variable's distribution before truncation.
double probability_between(const RandomStrength& v, double lo, double hi);

// One sample's values, one per variable in the order of spec.variables. Correlated pairs
// are drawn together from two independent normals z1, z2 through the Cholesky factor of
// [[1, r], [r, 1]]: y1 = z1, y2 = r z1 + sqrt(1 - r^2) z2. A value outside its [min, max]
// draws the variable (or its pair) again. Throws std::runtime_error when a million draws of
// one variable all miss its bounds (the reader refuses bounds holding less than 0.1 % of a
// variable's distribution).
std::vector<double> draw_sample(const RandomStrengths& spec, std::uint64_t seed,
                                std::uint64_t index);

// `consolidated` (from consolidate()) with the scene's joint materials and the world's
// materials taking the sample's values: the trials' joint laws (scene_joint_laws) rebuilt
// from `scene_joints` with the drawn properties; a plastic material's cohesion, friction
// angle (its dilation angle kept no larger) or tension cut-off set; the water table's fill.
World with_sampled_strengths(const World& consolidated,
                             const std::vector<JointMaterial>& scene_joints,
                             const RandomStrengths& spec, const std::vector<double>& values);

// The Wilson score interval of a proportion, k successes in n trials (Wilson 1927):
// (p + z^2/2n -+ z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n), p = k/n. z = 1.959964: 95 %.
// Unlike p -+ z sqrt(p(1-p)/n) it keeps within [0, 1] and is not empty at k = 0 or n.
struct ProportionInterval {
  double low = 0.0;
  double high = 1.0;
};
ProportionInterval wilson_interval(long successes, long trials, double z = 1.959963984540054);

}  // namespace dda
