// Material-point spec JSON in (`dda material-point SPEC.json`): a material, a plane mode, an
// initial stress and a path of strain and stress targets. The format is documented in
// docs/material-point-format.md; keep the two in step. Every error names the file and the
// place in it and is thrown as InputError, as for scenes.
#pragma once

#include <string>
#include <vector>

#include "io/scene_reader.hpp"
#include "materials/material.hpp"
#include "materials/material_point.hpp"
#include "materials/voigt4.hpp"
#include "solver/scene.hpp"

namespace dda {

struct MaterialPointSpec {
  std::string source;  // file name
  Material material;   // named "material"; its parameters carry the spec's plane mode
  Vec4 initial_stress = Vec4::Zero();  // sxx, syy, szz, sxy (Pa), tension positive
  std::vector<PathSegment> path;       // at least one segment, each with steps >= 1

  const MaterialParameters& parameters() const { return material.parameters; }
};

// Reads and validates a spec file. Throws InputError.
MaterialPointSpec read_material_point_file(const std::string& path);

// Validates spec JSON text; `source` names it in messages. Throws InputError.
MaterialPointSpec parse_material_point_text(const std::string& text, const std::string& source);

}  // namespace dda
