// The material vocabulary (MFront's behaviour data): parameters, the state carried from step
// to step, and what a return gives back (stress, state, consistent tangent, status). The
// yield surfaces and returns include this; materials/material.hpp is the model switch over
// them (integrate).
//
// Strain-driven and total: the stress is never accumulated. With the plastic strain e_p of
// the start state and an initial stress s0, the trial stress is
//   s_trial = s0 + D (e - e_p),  e = (exx, eyy, ezz = 0, gxy)       (plane strain, voigt4.hpp)
// and a return map (return_*.hpp) brings it back onto the yield surface. Tension positive.
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "common/enum_names.hpp"
#include "kinematics/types.hpp"
#include "materials/elastic.hpp"
#include "materials/hardening.hpp"
#include "materials/voigt4.hpp"

namespace dda {

enum class MaterialModel { Elastic, DruckerPrager, MohrCoulomb };

// The scene names of the models (the contract of materials.*.model).
inline constexpr EnumName<MaterialModel> kMaterialModelNames[] = {
    {MaterialModel::Elastic, "elastic"},
    {MaterialModel::DruckerPrager, "drucker_prager"},
    {MaterialModel::MohrCoulomb, "mohr_coulomb"},
};
inline std::string_view model_name(MaterialModel m) { return name_in(kMaterialModelNames, m); }

// How the Drucker-Prager cone is matched to the Mohr-Coulomb friction angle and cohesion
// (yield_drucker_prager.hpp).
enum class DruckerPragerMatch { Outer, Inner, PlaneStrain };

// Each model declares its own parameters, the way an MFront behaviour declares its own
// properties; what every model has (the elastic constants, the density) lives in
// MaterialParameters beside the model's.

// The elastic model has no parameters beyond the elastic constants.
struct ElasticOnly {};

// The strength and flow the two plastic models share, in Mohr-Coulomb's terms (the
// Drucker-Prager cone is matched to them).
struct FrictionalStrength {
  double cohesion = 0.0;        // Pa, >= 0 (the cohesion at eps_p = 0)
  double friction_angle = 0.0;  // degrees, [0, 90)
  double dilation_angle = 0.0;  // degrees, [0, friction_angle]; = friction: associated flow
  // Cohesion against equivalent plastic strain, piecewise linear, constant beyond the ends.
  // Empty: constant `cohesion`. Given: its value at eps_p = 0 must equal `cohesion`.
  std::vector<HardeningPoint> hardening;
};

struct DruckerPragerParameters : FrictionalStrength {
  DruckerPragerMatch match = DruckerPragerMatch::PlaneStrain;
};

struct MohrCoulombParameters : FrictionalStrength {
  // The tension cut-off, a Rankine plane s_max = tensile_strength (Pa, >= 0). Absent: no
  // cut-off (the Mohr-Coulomb surface alone, its apex at c cot phi); 0: no tension at all
  // (s_max <= 0). It does not soften with the cohesion.
  std::optional<double> tensile_strength;
};

// A plastic model's parameters (MohrCoulombParameters or DruckerPragerParameters) from its
// strength, without hardening and with its other parameters at their defaults (no cut-off,
// the plane-strain match): for code-built materials and tests.
template <class Model>
Model plastic_parameters(double cohesion, double friction_angle, double dilation_angle) {
  Model p;
  p.cohesion = cohesion;
  p.friction_angle = friction_angle;
  p.dilation_angle = dilation_angle;
  return p;
}

// The alternatives in the order of MaterialModel, so a model is its index.
using ModelParameters = std::variant<ElasticOnly, DruckerPragerParameters, MohrCoulombParameters>;
template <MaterialModel M>
using ParametersOf = std::variant_alternative_t<static_cast<std::size_t>(M), ModelParameters>;
static_assert(std::is_same_v<ParametersOf<MaterialModel::Elastic>, ElasticOnly>);
static_assert(std::is_same_v<ParametersOf<MaterialModel::DruckerPrager>, DruckerPragerParameters>);
static_assert(std::is_same_v<ParametersOf<MaterialModel::MohrCoulomb>, MohrCoulombParameters>);

struct MaterialParameters {
  double young = 0.0;    // Pa, > 0
  double poisson = 0.0;  // (-1, 0.5)
  double density = 0.0;  // kg/m^3, > 0 (not used by the returns; the blocks' mass)
  ModelParameters model_parameters;  // ElasticOnly unless set
  // Plastic models are plane strain only (validate_material rejects plane stress).
  PlaneMode plane = PlaneMode::Strain;

  MaterialModel model() const { return static_cast<MaterialModel>(model_parameters.index()); }
};

// The plastic models' shared strength and flow; nullptr for the elastic model.
inline const FrictionalStrength* frictional_strength(const MaterialParameters& p) {
  if (const auto* dp = std::get_if<DruckerPragerParameters>(&p.model_parameters)) return dp;
  if (const auto* mc = std::get_if<MohrCoulombParameters>(&p.model_parameters)) return mc;
  return nullptr;
}
inline FrictionalStrength* frictional_strength(MaterialParameters& p) {
  return const_cast<FrictionalStrength*>(frictional_strength(std::as_const(p)));
}

// What a material point carries from step to step.
//
// eps_p, the equivalent plastic strain, is the strain-like variable conjugate to the
// cohesion (de Souza Neto, Peric and Owen 2008, sections 6.4 and 8.2): its rate times c is
// the plastic dissipation of associated flow. Mohr-Coulomb: d eps_p = 2 cos(phi) times the
// sum of the plane multipliers (on the main plane with fixed axes, eps_p = cos(phi) (e_p1 -
// e_p3)); Drucker-Prager: d eps_p = xi d gamma. The tension cut-off's flow leaves it (and so
// the cohesion) unchanged.
struct MaterialState {
  Vec4 plastic_strain = Vec4::Zero();  // (xx, yy, zz, xy), engineering shear; zz is not zero
  double eps_p = 0.0;
};

// Which return the stress took. Tension: the cut-off is active (alone or with the
// Mohr-Coulomb surface; MaterialResult::active_planes tells which).
enum class Branch { Elastic, Plane, Edge, Apex, Cone, Tension };
// The names of the branches in the output files (summary.json, material-point CSV).
inline constexpr EnumName<Branch> kBranchNames[] = {
    {Branch::Elastic, "elastic"}, {Branch::Plane, "plane"}, {Branch::Edge, "edge"},
    {Branch::Apex, "apex"},       {Branch::Cone, "cone"},   {Branch::Tension, "tension"},
};
inline const char* branch_name(Branch b) { return name_in(kBranchNames, b).data(); }

struct MaterialStatus {
  bool converged = true;
  std::string reason;  // why it failed; empty when converged
  // Retry with this fraction of the strain increment (substepping); 0 when a smaller
  // increment cannot cure the failure (e.g. no return exists for these parameters).
  double suggested_fraction = 1.0;
};

struct MaterialResult {
  Vec4 stress = Vec4::Zero();  // (sxx, syy, szz, sxy); plane stress: szz = 0
  MaterialState state;
  Mat3 tangent = Mat3::Zero();  // d(sxx, syy, sxy) / d(exx, eyy, gxy), consistent
  Branch branch = Branch::Elastic;
  MaterialStatus status;
  // Mohr-Coulomb: the planes of the return in sorted principal space, a bitmask of
  // MohrCoulombPlane (yield_mohr_coulomb.hpp); 0 when elastic. For diagnostics and tests.
  unsigned active_planes = 0;
};

// True for the models with a yield surface.
inline bool is_plastic(MaterialModel m) { return m != MaterialModel::Elastic; }

}  // namespace dda
