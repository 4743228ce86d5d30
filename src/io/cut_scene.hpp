// The scene a cut model gives (`dda cut`): an ordinary scene JSON that `dda run`
// reads, laid out to be edited by hand. The model's scene keys are copied as given.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cutting/model.hpp"
#include "io/model_reader.hpp"
#include "solver/scene.hpp"

namespace dda {

struct CutScene {
  nlohmann::ordered_json scene;
  // Joint materials of the model that no pair of blocks uses: left out of the scene, where
  // the scene reader would warn about them (docs/scene-format.md, joint_materials).
  std::vector<std::string> unused_joint_materials;
  // Bolt patterns some of whose bolts hold nothing (both ends in one block or in fixed rock):
  // one line each, for a note on stderr.
  std::vector<std::string> bolts_left_out;
  // Every bolt of the scene (the model's own and the patterns'), from head to far end: for
  // the cut's picture.
  std::vector<std::pair<Vec2, Vec2>> bolt_lines;
};

// The scene: description (the model's, or one naming the model), gravity, plane, control,
// materials, joint_materials ("default" and those used), blocks (vertices, material, fixed
// when fixed) and joints (the pairs of a non-default joint material), then what the model
// carries of pins, point_loads, monitors, bolts, water, base_motion and stages, as given.
// `scene_path`: where the scene will be written; a base_motion record the model names
// relative to itself is named relative to it (empty: left as given).
CutScene cut_scene(const Model& model, const CutModel& cut, const std::string& scene_path = "");

// The scene's text: objects indented by 2, one key a line; each block and each joint on
// one line; numbers as the shortest text that reads back as the same double.
std::string scene_text(const nlohmann::ordered_json& scene);

// The cut's scene text read back as `dda run` reads it, `scene_name` naming it. A cut whose
// blocks a scene cannot hold (a block too thin to have an area at the reader's tolerance),
// or a key the model carries into the scene (a pin, a bolt, a phreatic line) that does not
// fit the cut's blocks, is the model's doing: an InputError naming `model_source`, at the
// key's place when there is one. A warning of the reader's is such an error too.
Scene read_back_cut_scene(const std::string& text, const std::string& scene_name,
                          const std::string& model_source);

}  // namespace dda
