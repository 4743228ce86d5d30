// Cutting-model JSON in (`dda cut`): parsing and validation at the boundary, as
// the scene reader does for scenes. docs/model-format.md documents the format; keep the two
// in step. Every error names the file and the place in it ("model.json:
// joint_sets[1].spacing: ...") and is thrown as InputError.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "cutting/model.hpp"

namespace dda {

struct Model {
  ModelSpec spec;
  // The keys copied into the cut scene as given (each checked by the scene's own rules):
  // description, gravity, plane, control, materials, joint_materials.
  nlohmann::json scene_settings;
  std::string source;
};

// Validates model JSON text; `source` names it in messages. Throws InputError.
Model parse_model_text(const std::string& text, const std::string& source);

// Reads and validates a model file. Throws InputError.
Model read_model_file(const std::string& path);

}  // namespace dda
