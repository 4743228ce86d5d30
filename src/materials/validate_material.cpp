#include "materials/validate_material.hpp"

#include <cmath>
#include <sstream>

namespace dda {

namespace {

std::string number(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

ParameterError error(std::string key, std::string message) {
  return {std::move(key), std::move(message)};
}

}  // namespace

std::optional<MaterialModel> parse_model(std::string_view name) {
  return value_in(kMaterialModelNames, name);
}

std::optional<DruckerPragerMatch> parse_match(std::string_view name) {
  if (name == "outer") return DruckerPragerMatch::Outer;
  if (name == "inner") return DruckerPragerMatch::Inner;
  if (name == "plane_strain") return DruckerPragerMatch::PlaneStrain;
  return std::nullopt;
}

ParameterError unknown_match(std::string_view name) {
  return error("match", "unknown match \"" + std::string(name) +
                            "\"; expected \"outer\", \"inner\" or \"plane_strain\"");
}

ParameterError unknown_model(std::string_view name) {
  return error("model", "unknown model \"" + std::string(name) +
                            "\"; expected \"elastic\", \"drucker_prager\" or \"mohr_coulomb\"");
}

std::optional<ParameterError> check_elasticity(const MaterialParameters& p) {
  if (!(p.young > 0.0)) return error("young", "must be > 0, got " + number(p.young));
  if (!(p.poisson > -1.0 && p.poisson < 0.5))
    return error("poisson", "must be in (-1, 0.5), got " + number(p.poisson));
  if (!(p.density > 0.0)) return error("density", "must be > 0, got " + number(p.density));
  return std::nullopt;
}

std::optional<ParameterError> check_angles(const MaterialParameters& m) {
  const FrictionalStrength* p = frictional_strength(m);
  if (!p) return std::nullopt;
  if (!(p->friction_angle >= 0.0 && p->friction_angle < 90.0))
    return error("friction_angle", "must be in [0, 90) degrees, got " + number(p->friction_angle));
  if (!(p->dilation_angle >= 0.0))
    return error("dilation_angle", "must be >= 0 degrees, got " + number(p->dilation_angle));
  if (p->dilation_angle > p->friction_angle)
    return error("dilation_angle", "must not exceed the friction angle (" +
                                       number(p->friction_angle) + " degrees), got " +
                                       number(p->dilation_angle));
  return std::nullopt;
}

std::optional<ParameterError> check_cohesion(const MaterialParameters& m) {
  const FrictionalStrength* p = frictional_strength(m);
  if (!p) return std::nullopt;
  if (!(p->cohesion >= 0.0)) return error("cohesion", "must be >= 0 Pa, got " + number(p->cohesion));
  for (std::size_t i = 0; i < p->hardening.size(); ++i) {
    const HardeningPoint& h = p->hardening[i];
    const std::string at = "hardening[" + std::to_string(i) + "]";
    if (!(h.eps_p >= 0.0)) return error(at, "eps_p must be >= 0, got " + number(h.eps_p));
    if (!(h.cohesion >= 0.0))
      return error(at, "cohesion must be >= 0 Pa, got " + number(h.cohesion));
    if (i > 0 && !(h.eps_p > p->hardening[i - 1].eps_p))
      return error(at, "eps_p must increase along the table, got " + number(h.eps_p) + " after " +
                           number(p->hardening[i - 1].eps_p));
  }
  if (!p->hardening.empty()) {
    // The table gives c(0); `cohesion` must agree so the two cannot tell different stories.
    // Relative 1e-12: a number written twice, at most a few ulps of decimal conversion.
    const double c0 = CohesionLaw(p->hardening, p->cohesion).value(0.0);
    if (std::abs(c0 - p->cohesion) > 1e-12 * std::max(std::abs(c0), std::abs(p->cohesion)))
      return error("cohesion", "is " + number(p->cohesion) + " Pa but the hardening table gives " +
                                   number(c0) + " Pa at eps_p = 0");
  }
  if (p->cohesion == 0.0 && p->friction_angle == 0.0)
    return error("cohesion", "a plastic material needs cohesion > 0 or friction_angle > 0");
  return std::nullopt;
}

std::optional<ParameterError> check_tension_cutoff(const MaterialParameters& m) {
  const auto* p = std::get_if<MohrCoulombParameters>(&m.model_parameters);
  if (!p || !p->tensile_strength) return std::nullopt;
  if (!(*p->tensile_strength >= 0.0))
    return error("tensile_strength", "must be >= 0 Pa, got " + number(*p->tensile_strength));
  return std::nullopt;
}

std::optional<ParameterError> check_match(const MaterialParameters& m) {
  const auto* p = std::get_if<DruckerPragerParameters>(&m.model_parameters);
  if (!p) return std::nullopt;
  switch (p->match) {
    case DruckerPragerMatch::Outer:
    case DruckerPragerMatch::Inner:
    case DruckerPragerMatch::PlaneStrain:
      return std::nullopt;
  }
  return error("match", "unknown match; expected \"outer\", \"inner\" or \"plane_strain\"");
}

std::optional<ParameterError> check_plane(const MaterialParameters& p) {
  if (is_plastic(p.model()) && p.plane != PlaneMode::Strain)
    return error("model",
                 "plastic models (\"drucker_prager\", \"mohr_coulomb\") need plane "
                 "strain; the scene is plane stress");
  return std::nullopt;
}

std::optional<ParameterError> validate_material(const MaterialParameters& p) {
  for (auto check : {check_elasticity, check_angles, check_cohesion, check_tension_cutoff,
                     check_match, check_plane})
    if (auto e = check(p)) return e;
  return std::nullopt;
}

}  // namespace dda
