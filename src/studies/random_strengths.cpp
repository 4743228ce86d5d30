#include "studies/random_strengths.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "materials/material_types.hpp"
#include "solver/stages.hpp"

namespace dda {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;
// Draws of one variable (or pair) before the bounds are taken as unreachable. The reader
// keeps at least 0.1 % of each distribution inside its bounds, so a million misses has a
// probability below 0.999^1e6 = e^-1000.
constexpr int kMostDraws = 1000000;

bool within(const RandomStrength& v, double x) { return x >= v.min && x <= v.max; }

[[noreturn]] void unreachable(const RandomStrength& v) {
  std::string message = "random_strengths: ";
  message += v.name;
  message += ".";
  message += strength_property_name(v.property);
  message += ": a million draws all fell outside its bounds";
  throw std::runtime_error(message);
}

// Which variable is paired with which (-1: none), and the coefficient.
struct Pairing {
  std::vector<int> partner;
  std::vector<double> coefficient;
};

Pairing pairing_of(const RandomStrengths& spec) {
  Pairing p{std::vector<int>(spec.variables.size(), -1),
            std::vector<double>(spec.variables.size(), 0.0)};
  for (const StrengthCorrelation& c : spec.correlations) {
    p.partner[static_cast<std::size_t>(c.first)] = c.second;
    p.partner[static_cast<std::size_t>(c.second)] = c.first;
    p.coefficient[static_cast<std::size_t>(c.first)] = c.coefficient;
    p.coefficient[static_cast<std::size_t>(c.second)] = c.coefficient;
  }
  return p;
}

void set_joint_property(JointMaterial& j, StrengthProperty p, double x) {
  switch (p) {
    case StrengthProperty::FrictionAngle: j.friction_angle = x; break;
    case StrengthProperty::Cohesion: j.cohesion = x; break;
    case StrengthProperty::TensileStrength: j.tensile_strength = x; break;
    case StrengthProperty::WaterFill: break;  // the reader gives it the water only
  }
}

void set_material_property(MaterialParameters& m, StrengthProperty p, double x) {
  FrictionalStrength* f = frictional_strength(m);
  if (f == nullptr) return;  // the reader allows plastic materials only
  switch (p) {
    case StrengthProperty::FrictionAngle:
      f->friction_angle = x;
      // The material library requires psi <= phi (as reduced_material keeps it).
      f->dilation_angle = std::min(f->dilation_angle, x);
      break;
    case StrengthProperty::Cohesion: f->cohesion = x; break;
    case StrengthProperty::TensileStrength:
      if (auto* mc = std::get_if<MohrCoulombParameters>(&m.model_parameters)) mc->tensile_strength = x;
      break;
    case StrengthProperty::WaterFill: break;  // the reader gives it the water only
  }
}

}  // namespace

double standard_normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

std::mt19937_64 sample_generator(std::uint64_t seed, std::uint64_t index) {
  // seed_seq mixes its 32-bit words by an algorithm the standard specifies, so nearby
  // (seed, index) pairs give unrelated generator states.
  std::seed_seq words{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                      static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32)};
  return std::mt19937_64(words);
}

double open_uniform(std::mt19937_64& gen) {
  return (static_cast<double>(gen() >> 11) + 0.5) * 0x1p-53;
}

double standard_normal(std::mt19937_64& gen) {
  const double u1 = open_uniform(gen);
  const double u2 = open_uniform(gen);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
}

LogNormalParameters lognormal_parameters(double mean, double standard_deviation) {
  const double cv = standard_deviation / mean;
  LogNormalParameters p;
  p.sigma = std::sqrt(std::log1p(cv * cv));
  p.mu = std::log(mean) - 0.5 * p.sigma * p.sigma;
  return p;
}

double strength_at(const RandomStrength& v, double z) {
  if (v.distribution == StrengthDistribution::Normal) return v.mean + v.standard_deviation * z;
  const LogNormalParameters p = lognormal_parameters(v.mean, v.standard_deviation);
  return std::exp(p.mu + p.sigma * z);
}

double probability_between(const RandomStrength& v, double lo, double hi) {
  if (!(hi >= lo)) return 0.0;
  if (v.distribution == StrengthDistribution::Normal) {
    return standard_normal_cdf((hi - v.mean) / v.standard_deviation) -
           standard_normal_cdf((lo - v.mean) / v.standard_deviation);
  }
  if (hi <= 0.0) return 0.0;
  const LogNormalParameters p = lognormal_parameters(v.mean, v.standard_deviation);
  const double upper = std::isinf(hi) ? 1.0 : standard_normal_cdf((std::log(hi) - p.mu) / p.sigma);
  const double lower = lo <= 0.0 ? 0.0 : standard_normal_cdf((std::log(lo) - p.mu) / p.sigma);
  return upper - lower;
}

std::vector<double> draw_sample(const RandomStrengths& spec, std::uint64_t seed,
                                std::uint64_t index) {
  std::mt19937_64 gen = sample_generator(seed, index);
  const Pairing pairs = pairing_of(spec);
  const std::size_t n = spec.variables.size();
  std::vector<double> values(n, 0.0);
  // In the order of the variables; a pair is drawn at its first variable's place.
  for (std::size_t i = 0; i < n; ++i) {
    const RandomStrength& v = spec.variables[i];
    const int partner = pairs.partner[i];
    if (partner >= 0 && static_cast<std::size_t>(partner) < i) continue;  // drawn with it
    if (partner < 0) {
      int draws = 0;
      do {
        if (++draws > kMostDraws) unreachable(v);
        values[i] = strength_at(v, standard_normal(gen));
      } while (!within(v, values[i]));
      continue;
    }
    const auto j = static_cast<std::size_t>(partner);
    const RandomStrength& w = spec.variables[j];
    const double r = pairs.coefficient[i];
    int draws = 0;
    do {
      if (++draws > kMostDraws) unreachable(v);
      const double z1 = standard_normal(gen);
      const double z2 = standard_normal(gen);
      values[i] = strength_at(v, z1);
      values[j] = strength_at(w, r * z1 + std::sqrt(1.0 - r * r) * z2);
    } while (!within(v, values[i]) || !within(w, values[j]));
  }
  return values;
}

World with_sampled_strengths(const World& consolidated,
                             const std::vector<JointMaterial>& scene_joints,
                             const RandomStrengths& spec, const std::vector<double>& values) {
  World w = consolidated;
  std::vector<JointMaterial> joints = scene_joints;
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    const RandomStrength& v = spec.variables[i];
    const auto k = static_cast<std::size_t>(v.index);
    if (v.owner == StrengthOwner::JointMaterial) {
      set_joint_property(joints[k], v.property, values[i]);
    } else if (v.owner == StrengthOwner::Water) {
      // The trial starts from the consolidation's state under the scene's own table and
      // finds its balance (or fails) under the drawn one, as under reduced strengths.
      if (w.water) w.water->fill = values[i];
    } else {
      set_material_property(w.materials[k].parameters, v.property, values[i]);
    }
  }
  // Where the trials read the scene's joint laws (scene_joint_laws): a staged world keeps
  // them with its stages, as consolidate() left them.
  std::vector<JointLaw> laws;
  for (const JointMaterial& j : joints) laws.push_back(joint_law_of(j));
  if (w.stages.stages.empty()) {
    w.joint_laws = std::move(laws);
  } else {
    w.stages.joint_laws = std::move(laws);
  }
  return w;
}

ProportionInterval wilson_interval(long successes, long trials, double z) {
  if (trials <= 0) return {0.0, 1.0};
  const double n = static_cast<double>(trials);
  const double p = static_cast<double>(successes) / n;
  const double z2n = z * z / n;
  const double centre = (p + 0.5 * z2n) / (1.0 + z2n);
  const double half = z * std::sqrt(p * (1.0 - p) / n + z2n / (4.0 * n)) / (1.0 + z2n);
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

}  // namespace dda
