// One material object in, as written in a scene's `materials.NAME` and in a material-point
// spec's `material` (the same format, so a material can be pasted from one to the other).
// docs/scene-format.md documents the keys. Every error names the place and is thrown as
// InputError.
#pragma once

#include <string>

#include "io/json_input.hpp"
#include "materials/elastic.hpp"
#include "solver/scene.hpp"

namespace dda::input {

// "strain" or "stress" (a scene's and a spec's `plane`).
PlaneMode read_plane(const Field& f);

// Reads the material object `f` and validates it for `plane` (the plastic models are plane
// strain only). The key set depends on `model`: a key of another model is an error naming
// it, and the parameter checks are materials/validate_material's, reported at the key they
// concern (`materials.soil.hardening[1]`).
Material read_material(const std::string& name, const Field& f, PlaneMode plane);

}  // namespace dda::input
