// Cost of one integrate() call of the material library on each return branch:
// elastic, Mohr-Coulomb plane, edge, apex and tension cut-off, Drucker-Prager cone and apex,
// and the elastic model as the baseline. Each case is a trial stress (given as the initial
// stress, at zero strain: the trial is s0 + D e either way) with principal axes turned away
// from x, so the principal decomposition and the rotation back are paid as in use. Run:
//   build/release/dda_bench --benchmark_filter=Integrate
#include <benchmark/benchmark.h>

#include <string>

#include "materials/material.hpp"
#include "materials/principal.hpp"

namespace {

constexpr double kC = 1e6;  // cohesion, Pa

dda::MaterialParameters material(dda::MaterialModel model) {
  dda::MaterialParameters p;
  p.young = 20e9;
  p.poisson = 0.3;
  p.density = 2500.0;
  if (model == dda::MaterialModel::MohrCoulomb)
    p.model_parameters = dda::plastic_parameters<dda::MohrCoulombParameters>(kC, 30.0, 30.0);
  else if (model == dda::MaterialModel::DruckerPrager)
    p.model_parameters = dda::plastic_parameters<dda::DruckerPragerParameters>(kC, 30.0, 30.0);
  return p;
}

struct Case {
  dda::MaterialParameters params;
  dda::Vec4 trial;  // (sxx, syy, szz, sxy)
  dda::Branch expected;
};

// Principal values (a, b, z) in units of c, a along 0.5 rad from x.
dda::Vec4 trial_of(double a, double b, double z) {
  return dda::stress_from_principal(dda::Vec3(a, b, z) * kC, 0.5);
}

// phi = 30 degrees: the Mohr-Coulomb surface is 1.5 s1 - 0.5 s3 <= 1.73 c, its apex at
// 1.73 c; the Drucker-Prager cone (plane-strain match) sqrt(J2) + 0.48 p <= 0.83 c.
Case make_case(const std::string& name) {
  using dda::Branch;
  using dda::MaterialModel;
  const auto mc = material(MaterialModel::MohrCoulomb);
  const auto dp = material(MaterialModel::DruckerPrager);
  if (name == "elastic_model") return {material(MaterialModel::Elastic), trial_of(-1, -3, -2), Branch::Elastic};
  if (name == "mc_elastic") return {mc, trial_of(-1, -3, -2), Branch::Elastic};
  if (name == "mc_plane") return {mc, trial_of(0.5, -5, -2.5), Branch::Plane};
  if (name == "mc_edge") return {mc, trial_of(0.05, -6, 0), Branch::Edge};
  if (name == "mc_apex") return {mc, trial_of(3, 2.9, 2.95), Branch::Apex};
  if (name == "mc_tension") {
    auto p = mc;
    std::get<dda::MohrCoulombParameters>(p.model_parameters).tensile_strength = 0.5 * kC;
    return {p, trial_of(0.8, -0.5, 0), Branch::Tension};
  }
  if (name == "dp_elastic") return {dp, trial_of(-1, -3, -2), Branch::Elastic};
  if (name == "dp_cone") return {dp, trial_of(1, -7, -3), Branch::Cone};
  if (name == "dp_apex") return {dp, trial_of(3, 2.9, 2.95), Branch::Apex};
  return {};
}

void BM_Integrate(benchmark::State& state, const std::string& name) {
  const Case c = make_case(name);
  const dda::MaterialState start;
  const dda::Vec3 strain = dda::Vec3::Zero();
  const dda::MaterialResult check = dda::integrate(c.params, start, strain, c.trial);
  if (!check.status.converged || check.branch != c.expected) {
    state.SkipWithError((name + ": landed on " + dda::branch_name(check.branch) +
                         (check.status.converged ? "" : " (failed)") + ", not " +
                         dda::branch_name(c.expected))
                            .c_str());
    return;
  }
  for (auto _ : state) {
    dda::MaterialResult r = dda::integrate(c.params, start, strain, c.trial);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK_CAPTURE(BM_Integrate, elastic_model, std::string("elastic_model"));
BENCHMARK_CAPTURE(BM_Integrate, mc_elastic, std::string("mc_elastic"));
BENCHMARK_CAPTURE(BM_Integrate, mc_plane, std::string("mc_plane"));
BENCHMARK_CAPTURE(BM_Integrate, mc_edge, std::string("mc_edge"));
BENCHMARK_CAPTURE(BM_Integrate, mc_apex, std::string("mc_apex"));
BENCHMARK_CAPTURE(BM_Integrate, mc_tension, std::string("mc_tension"));
BENCHMARK_CAPTURE(BM_Integrate, dp_elastic, std::string("dp_elastic"));
BENCHMARK_CAPTURE(BM_Integrate, dp_cone, std::string("dp_cone"));
BENCHMARK_CAPTURE(BM_Integrate, dp_apex, std::string("dp_apex"));

}  // namespace
