#include "materials/material.hpp"

#include <type_traits>
#include <utility>
#include <variant>

#include "materials/plastic_return.hpp"
#include "materials/return_drucker_prager.hpp"
#include "materials/return_mohr_coulomb.hpp"

namespace dda {
namespace {

// Plane stress is elastic only: s = s0 + D e in plane, szz = 0.
MaterialResult integrate_plane_stress(const MaterialParameters& params, const MaterialState& start,
                                      const Vec3& strain, const Vec4& s0) {
  MaterialResult r;
  r.state = start;
  r.tangent = elastic_matrix(params.young, params.poisson, PlaneMode::Stress);
  if (is_plastic(params.model())) {
    r.status = {false, "plastic models are plane strain only", 0.0};
    return r;
  }
  const Vec3 s = in_plane(s0) + r.tangent * strain;
  r.stress = {s[0], s[1], 0.0, s[2]};
  return r;
}

}  // namespace

MaterialResult integrate(const MaterialParameters& params, const MaterialState& start,
                         const Vec3& total_strain, const Vec4& initial_stress) {
  if (params.plane == PlaneMode::Stress)
    return integrate_plane_stress(params, start, total_strain, initial_stress);

  const ElasticModuli moduli = elastic_moduli(params.young, params.poisson);
  const Vec4 trial = initial_stress +
                     elastic_matrix4(moduli) * (plane_strain4(total_strain) - start.plastic_strain);
  // The variant's alternative is the model: each return gets its own parameters only.
  PlasticReturn ret = std::visit(
      [&](const auto& model) {
        using Model = std::decay_t<decltype(model)>;
        if constexpr (std::is_same_v<Model, DruckerPragerParameters>)
          return return_drucker_prager(model, moduli, trial, start.eps_p);
        else if constexpr (std::is_same_v<Model, MohrCoulombParameters>)
          return return_mohr_coulomb(model, moduli, trial, start.eps_p);
        else
          return elastic_return(trial, start.eps_p, elastic_matrix4(moduli));
      },
      params.model_parameters);
  MaterialResult r;
  r.stress = ret.stress;
  r.tangent = in_plane(ret.tangent);
  r.branch = ret.branch;
  r.active_planes = ret.active_planes;
  r.status = std::move(ret.status);
  r.state.eps_p = ret.eps_p;
  // s = s_trial - D (e_p - e_p_start): the plastic strain increment is D^-1 (s_trial - s).
  r.state.plastic_strain = start.plastic_strain + elastic_compliance4(moduli, trial - ret.stress);
  return r;
}

}  // namespace dda
