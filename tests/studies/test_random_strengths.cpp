// The sampler of `dda fos --samples` (studies/random_strengths.hpp) against the
// distributions it is asked for: moments of many draws, truncation, the correlation of
// drawn pairs, reproducibility by (seed, index); and the Wilson interval against a value
// worked by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "studies/random_strengths.hpp"

namespace {

using namespace dda;

constexpr long kDraws = 20000;

RandomStrength variable(StrengthDistribution d, double mean, double sd) {
  RandomStrength v;
  v.name = "bedding";
  v.property = StrengthProperty::Cohesion;
  v.distribution = d;
  v.mean = mean;
  v.standard_deviation = sd;
  return v;
}

struct DrawMoments {
  double mean = 0.0;
  double sd = 0.0;
};

DrawMoments moments(const std::vector<double>& x) {
  DrawMoments m;
  for (double v : x) m.mean += v;
  m.mean /= static_cast<double>(x.size());
  for (double v : x) m.sd += (v - m.mean) * (v - m.mean);
  m.sd = std::sqrt(m.sd / static_cast<double>(x.size() - 1));
  return m;
}

// The first variable of kDraws samples, sample k drawn from (seed, k).
std::vector<std::vector<double>> draws(const RandomStrengths& spec, std::uint64_t seed) {
  std::vector<std::vector<double>> out;
  for (long k = 0; k < kDraws; ++k) out.push_back(draw_sample(spec, seed, static_cast<std::uint64_t>(k)));
  return out;
}

std::vector<double> column(const std::vector<std::vector<double>>& rows, std::size_t i) {
  std::vector<double> out;
  for (const auto& r : rows) out.push_back(r[i]);
  return out;
}

double normal_pdf(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * M_PI); }

}  // namespace

TEST_CASE("normal and lognormal draws have the asked mean and standard deviation",
          "[fos][random]") {
  // Tolerances are 4 standard errors of the estimate over n = 20000 draws, so a correct
  // sampler fails them with probability below 1e-4 (and, with a fixed seed, never):
  // the mean's standard error is s / sqrt(n); the sample standard deviation's is
  // s sqrt((kappa - 1) / 4n) with kappa the kurtosis (3 for a normal, about 5.97 for the
  // lognormal of coefficient of variation 0.4 below).
  const double n = kDraws;
  {
    RandomStrengths spec;
    spec.variables.push_back(variable(StrengthDistribution::Normal, 30.0, 3.0));
    const DrawMoments m = moments(column(draws(spec, 42), 0));
    CHECK(std::abs(m.mean - 30.0) < 4.0 * 3.0 / std::sqrt(n));
    CHECK(std::abs(m.sd - 3.0) < 4.0 * 3.0 * std::sqrt(2.0 / (4.0 * n)));
  }
  {
    RandomStrengths spec;
    spec.variables.push_back(variable(StrengthDistribution::Lognormal, 2e4, 8e3));
    const std::vector<double> x = column(draws(spec, 7), 0);
    const DrawMoments m = moments(x);
    const double kurtosis = 5.97;
    CHECK(std::abs(m.mean - 2e4) < 4.0 * 8e3 / std::sqrt(n));
    CHECK(std::abs(m.sd - 8e3) < 4.0 * 8e3 * std::sqrt((kurtosis - 1.0) / (4.0 * n)));
    // Its logarithm is normal with sigma^2 = ln(1 + 0.4^2), mu = ln(2e4) - sigma^2 / 2.
    std::vector<double> logs;
    for (double v : x) logs.push_back(std::log(v));
    const LogNormalParameters p = lognormal_parameters(2e4, 8e3);
    REQUIRE(p.sigma == Approx(std::sqrt(std::log(1.16))).epsilon(1e-14));
    const DrawMoments ml = moments(logs);
    CHECK(std::abs(ml.mean - p.mu) < 4.0 * p.sigma / std::sqrt(n));
    CHECK(std::abs(ml.sd - p.sigma) < 4.0 * p.sigma * std::sqrt(2.0 / (4.0 * n)));
    for (double v : x) REQUIRE(v > 0.0);
  }
}

TEST_CASE("truncated draws stay within their bounds and have the truncated normal's mean",
          "[fos][random]") {
  RandomStrengths spec;
  RandomStrength v = variable(StrengthDistribution::Normal, 30.0, 5.0);
  v.min = 28.0;
  v.max = 33.0;
  spec.variables.push_back(v);
  const std::vector<double> x = column(draws(spec, 3), 0);
  for (double d : x) REQUIRE((d >= 28.0 && d <= 33.0));
  // The mean of N(mu, s) truncated to [a, b]: mu + s (pdf(alpha) - pdf(beta)) / (Phi(beta) -
  // Phi(alpha)), alpha = (a - mu)/s, beta = (b - mu)/s (Johnson, Kotz and Balakrishnan,
  // chapter 13). The truncated standard deviation is below (b - a) / sqrt(12) = 1.44, so 4
  // standard errors of the mean are below 0.041.
  const double alpha = -0.4, beta = 0.6;
  const double expected = 30.0 + 5.0 * (normal_pdf(alpha) - normal_pdf(beta)) /
                                     (standard_normal_cdf(beta) - standard_normal_cdf(alpha));
  CHECK(std::abs(moments(x).mean - expected) < 0.041);
  CHECK(probability_between(v, 28.0, 33.0) ==
        Approx(standard_normal_cdf(beta) - standard_normal_cdf(alpha)).epsilon(1e-14));
}

TEST_CASE("correlated pairs have the asked correlation", "[fos][random]") {
  RandomStrengths spec;
  spec.variables.push_back(variable(StrengthDistribution::Normal, 1e4, 2e3));
  RandomStrength phi = variable(StrengthDistribution::Normal, 30.0, 3.0);
  phi.property = StrengthProperty::FrictionAngle;
  spec.variables.push_back(phi);
  spec.correlations.push_back({0, 1, -0.5});
  const auto rows = draws(spec, 11);
  const std::vector<double> c = column(rows, 0), f = column(rows, 1);
  const DrawMoments mc = moments(c), mf = moments(f);
  double cov = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) cov += (c[k] - mc.mean) * (f[k] - mf.mean);
  const double r = cov / static_cast<double>(c.size() - 1) / (mc.sd * mf.sd);
  // The sample correlation's standard error is about (1 - r^2) / sqrt(n) = 0.0053: 4 of them.
  CHECK(std::abs(r + 0.5) < 4.0 * 0.75 / std::sqrt(static_cast<double>(kDraws)));
  // Each marginal keeps its own distribution.
  CHECK(std::abs(mf.mean - 30.0) < 4.0 * 3.0 / std::sqrt(static_cast<double>(kDraws)));
}

TEST_CASE("a sample's values depend on the seed and its index only", "[fos][random]") {
  RandomStrengths spec;
  spec.variables.push_back(variable(StrengthDistribution::Lognormal, 1e4, 3e3));
  RandomStrength phi = variable(StrengthDistribution::Normal, 30.0, 3.0);
  phi.property = StrengthProperty::FrictionAngle;
  phi.min = 25.0;
  spec.variables.push_back(phi);
  std::vector<std::vector<double>> forward, backward(100);
  for (std::uint64_t k = 0; k < 100; ++k) forward.push_back(draw_sample(spec, 2024, k));
  for (std::uint64_t k = 100; k-- > 0;) {
    draw_sample(spec, 99, k);  // other draws in between change nothing
    backward[k] = draw_sample(spec, 2024, k);
  }
  for (std::size_t k = 0; k < 100; ++k) REQUIRE(forward[k] == backward[k]);
  CHECK(draw_sample(spec, 2024, 0) != draw_sample(spec, 2025, 0));
  CHECK(draw_sample(spec, 2024, 0) != draw_sample(spec, 2024, 1));
  // Two generators of the same (seed, index) give the same stream, and uniforms stay
  // inside the open interval (Box-Muller takes log(u1)).
  std::mt19937_64 a = sample_generator(2024, 0), b = sample_generator(2024, 0);
  CHECK(a() == b());
  const double u = open_uniform(a);
  CHECK((u > 0.0 && u < 1.0));
}

TEST_CASE("the Wilson score interval of 3 in 10 is 0.108 to 0.603", "[fos][random]") {
  // Worked by hand: p = 0.3, z^2/n = 0.38415, centre (0.3 + 0.19207) / 1.38415 = 0.35550,
  // half-width 1.95996 sqrt(0.021 + 0.0096037) / 1.38415 = 0.24771.
  const ProportionInterval w = wilson_interval(3, 10);
  CHECK(w.low == Approx(0.10779).margin(1e-4));
  CHECK(w.high == Approx(0.60322).margin(1e-4));
  // At no failure it is not empty: [0, z^2 / (n + z^2)].
  const ProportionInterval zero = wilson_interval(0, 100);
  CHECK(zero.low == Approx(0.0).margin(1e-15));
  CHECK(zero.high == Approx(3.8415 / 103.8415).epsilon(1e-4));
}
