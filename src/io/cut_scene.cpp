#include "io/cut_scene.hpp"

#include <algorithm>
#include <set>

namespace dda {
namespace {

using ordered_json = nlohmann::ordered_json;

ordered_json block_json(const Polygon& vertices, const std::string& material, bool fixed) {
  ordered_json points = ordered_json::array();
  for (const Vec2& v : vertices) points.push_back({v.x(), v.y()});
  ordered_json block = {{"vertices", points}, {"material", material}};
  if (fixed) block["fixed"] = true;
  return block;
}

// One line, with a space after each comma and colon: {"vertices": [[0.0, 1.5], ...], ...}.
std::string one_line(const ordered_json& value) {
  std::string text;
  if (value.is_object()) {
    for (const auto& [key, item] : value.items()) {
      text += (text.empty() ? "{" : ", ") + ordered_json(key).dump() + ": " + one_line(item);
    }
    return text.empty() ? "{}" : text + "}";
  }
  if (value.is_array()) {
    for (const ordered_json& item : value) text += (text.empty() ? "[" : ", ") + one_line(item);
    return text.empty() ? "[]" : text + "]";
  }
  return value.dump();  // numbers: the shortest text that reads back as the same double
}

// Objects one key a line; a list of plain values on one line ([0.0, -9.81]); a list of
// objects or lists one element a line (a block, a joint, a hardening row), each on one line.
std::string layout(const ordered_json& value, const std::string& indent) {
  const std::string inner = indent + "  ";
  std::string text;
  if (value.is_object() && !value.empty()) {
    for (const auto& [key, item] : value.items()) {
      text += (text.empty() ? "{\n" : ",\n") + inner + ordered_json(key).dump() + ": " +
              layout(item, inner);
    }
    return text + "\n" + indent + "}";
  }
  const auto structured = [](const ordered_json& v) { return v.is_structured(); };
  const bool nested =
      value.is_array() && std::any_of(value.begin(), value.end(), structured);
  if (!nested) return one_line(value);
  for (const ordered_json& item : value) {
    text += (text.empty() ? "[\n" : ",\n") + inner + one_line(item);
  }
  return text + "\n" + indent + "]";
}

}  // namespace

CutScene cut_scene(const Model& model, const CutModel& cut) {
  CutScene out;
  const nlohmann::json& settings = model.scene_settings;
  ordered_json& scene = out.scene;
  scene["description"] = settings.contains("description")
                             ? settings.at("description").get<std::string>()
                             : "Cut by dda cut from " + model.source + " (seed " +
                                   std::to_string(model.spec.seed) + ")";
  for (const char* key : {"gravity", "plane", "control", "materials"}) {
    if (settings.contains(key)) scene[key] = ordered_json(settings.at(key));
  }
  std::set<std::string> used{kDefaultJointMaterial};
  for (const CutJoint& j : cut.joints) used.insert(j.joint_material);
  ordered_json joint_materials = ordered_json::object();
  for (const auto& [name, value] : settings.at("joint_materials").items()) {
    if (used.count(name) != 0) {
      joint_materials[name] = ordered_json(value);
    } else {
      out.unused_joint_materials.push_back(name);
    }
  }
  scene["joint_materials"] = joint_materials;
  ordered_json blocks = ordered_json::array();
  for (std::size_t i = 0; i < cut.cut.blocks.size(); ++i) {
    blocks.push_back(block_json(cut.cut.blocks[i], cut.materials[i], cut.fixed[i]));
  }
  scene["blocks"] = blocks;
  ordered_json joints = ordered_json::array();
  for (const CutJoint& j : cut.joints) {
    joints.push_back({{"blocks", {j.a, j.b}}, {"material", j.joint_material}});
  }
  if (!joints.empty()) scene["joints"] = joints;
  // Stages (e.g. a static consolidation with gravity ramped up, for dda fos) are copied as
  // the model gives them; the model reader has checked them as a scene's.
  if (settings.contains("stages")) scene["stages"] = ordered_json(settings.at("stages"));
  return out;
}

std::string scene_text(const ordered_json& scene) { return layout(scene, "") + "\n"; }

}  // namespace dda
