// Cutting-model JSON in (`dda cut`): parsing and validation at the boundary, as
// the scene reader does for scenes. docs/model-format.md documents the format; keep the two
// in step. Every error names the file and the place in it ("model.json:
// joint_sets[1].spacing: ...") and is thrown as InputError.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "cutting/model.hpp"

namespace dda {

// The scene keys a model carries that place something in the blocks (a point, a phreatic
// line over them): copied into the cut's scene and checked there, on its blocks.
inline constexpr std::string_view kKeysInBlocks[] = {"pins", "point_loads", "monitors", "bolts",
                                                     "water"};

// A row of rock bolts along a face of the domain (docs/model-format.md, "bolt_patterns"):
// heads every `spacing` metres along the face from `face_from` to `face_to` (the first at
// half a spacing), each bolt `length` long, dipping `dip` degrees below the horizontal into
// the rock, with a scene bolt's law (values per metre of thickness).
struct BoltPattern {
  std::string name;
  Vec2 face_from = Vec2::Zero();
  Vec2 face_to = Vec2::Zero();
  Vec2 direction = Vec2::Zero();  // unit, into the rock (resolved by the reader)
  double spacing = 0.0;
  double length = 0.0;
  double stiffness = 0.0;
  double pretension = 0.0;
  std::optional<double> yield_force;
  std::optional<double> rupture_extension;
};

struct Model {
  ModelSpec spec;
  std::vector<BoltPattern> bolt_patterns;
  // Per stage of the model (empty without stages): the region whose blocks the stage
  // removes (its "excavate_region"), turned into the scene stage's "excavate" by the cut.
  std::vector<std::optional<Polygon>> stage_excavations;
  // The keys copied into the cut scene as given (each checked by the scene's own rules):
  // description, gravity, plane, control, materials, joint_materials, stages, base_motion,
  // and those checked on the cut's blocks, kKeysInBlocks.
  nlohmann::json scene_settings;
  std::string source;
};

// Validates model JSON text; `source` names it in messages. Throws InputError.
Model parse_model_text(const std::string& text, const std::string& source);

// Reads and validates a model file. Throws InputError.
Model read_model_file(const std::string& path);

}  // namespace dda
