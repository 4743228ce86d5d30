// Scene JSON in: parsing and validation at the boundary. The only place that turns user
// input into a Scene; every error names the file and the place in it (e.g.
// "scene.json: blocks[3].vertices: ...") and is thrown as InputError.
#pragma once

#include <string>

#include "io/input_error.hpp"
#include "solver/scene.hpp"

namespace dda {

// Reads and validates a scene file. Throws InputError.
Scene read_scene_file(const std::string& path);

// Validates scene JSON text; `source` names it in messages. Throws InputError.
Scene parse_scene_text(const std::string& text, const std::string& source);

// The built-in default scene's JSON text (what `dda run` runs without a scene file).
const std::string& default_scene_text();
inline constexpr const char* kDefaultSceneName = "built-in default scene";

}  // namespace dda
