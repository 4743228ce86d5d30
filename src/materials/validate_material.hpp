// Checks of material parameters as pure functions, for the scene and material-point readers
// (io): each returns nothing when the input is fine, or the key at fault and a message.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "materials/material_types.hpp"

namespace dda {

struct ParameterError {
  std::string key;      // the parameter's key in the scene format, e.g. "friction_angle"
  std::string message;  // e.g. "must be in [0, 90) degrees, got 95"
};

// Names of the scene format (a contract: docs/scene-format.md, materials).
std::optional<MaterialModel> parse_model(
    std::string_view name);  // "elastic", "drucker_prager", "mohr_coulomb"
std::optional<DruckerPragerMatch> parse_match(
    std::string_view name);  // "outer", "inner", "plane_strain"
// The message for a `match` that parse_match does not know.
ParameterError unknown_match(std::string_view name);
ParameterError unknown_model(std::string_view name);

// One check each; validate_material runs them all and returns the first error.
std::optional<ParameterError> check_elasticity(
    const MaterialParameters& p);                                         // young, poisson, density
std::optional<ParameterError> check_angles(const MaterialParameters& p);  // friction, dilation
std::optional<ParameterError> check_cohesion(
    const MaterialParameters& p);  // cohesion, hardening table
std::optional<ParameterError> check_tension_cutoff(const MaterialParameters& p);
std::optional<ParameterError> check_match(const MaterialParameters& p);
std::optional<ParameterError> check_plane(
    const MaterialParameters& p);  // plastic needs plane strain
std::optional<ParameterError> validate_material(const MaterialParameters& p);

}  // namespace dda
