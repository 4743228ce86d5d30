#include "io/cut_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <string_view>

#include "io/input_error.hpp"
#include "io/json_input.hpp"
#include "io/scene_reader.hpp"
#include "cutting/block_labels.hpp"
#include "kinematics/polygon.hpp"

namespace dda {
namespace {

namespace fs = std::filesystem;
using ordered_json = nlohmann::ordered_json;

// `edge_joints`: the joint material of each edge ("" none); written only when an edge's is
// not the default, so that a block on default joints alone reads as before.
ordered_json block_json(const Polygon& vertices, const std::string& material, bool fixed,
                        const std::vector<std::string>& edge_joints,
                        const std::vector<EdgeBridge>& edge_bridges) {
  ordered_json points = ordered_json::array();
  for (const Vec2& v : vertices) points.push_back({v.x(), v.y()});
  ordered_json block = {{"vertices", points}, {"material", material}};
  if (fixed) block["fixed"] = true;
  const bool any = std::any_of(edge_joints.begin(), edge_joints.end(), [](const std::string& n) {
    return !n.empty() && n != kDefaultJointMaterial;
  });
  if (any) {
    ordered_json names = ordered_json::array();
    for (const std::string& n : edge_joints) names.push_back(n.empty() ? ordered_json() : ordered_json(n));
    block["edge_joints"] = names;
  }
  if (std::any_of(edge_bridges.begin(), edge_bridges.end(), [](const EdgeBridge& e) { return e.share > 0.0; })) {
    ordered_json list = ordered_json::array();
    for (const EdgeBridge& e : edge_bridges) {
      list.push_back(e.share > 0.0 ? ordered_json{{"material", e.material}, {"share", e.share}} : ordered_json());
    }
    block["edge_bridges"] = list;
  }
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

// The first block (in order) containing p, its boundary included, as the scene reader finds
// it; -1 when none does.
int block_at(const CutModel& cut, const Vec2& p) {
  for (std::size_t i = 0; i < cut.cut.blocks.size(); ++i) {
    if (contains_point(cut.cut.blocks[i], p)) return static_cast<int>(i);
  }
  return -1;
}

// The scene bolts of a model's bolt patterns: a head every spacing along each face (the first
// at half a spacing), 1 mm inside the rock along the bolt (a head exactly on the face could
// round to outside its block), the far end `length` beyond. A bolt whose two ends lie in one
// block, or in two fixed blocks, holds nothing and is left out (counted in `left_out`); a far
// end outside every block is the model's error.
ordered_json pattern_bolts(const Model& model, const CutModel& cut, std::vector<std::string>& left_out) {
  ordered_json bolts = ordered_json::array();
  for (std::size_t k = 0; k < model.bolt_patterns.size(); ++k) {
    const BoltPattern& p = model.bolt_patterns[k];
    const Vec2 along = p.face_to - p.face_from;
    const double face_length = along.norm();
    const double inset = std::min(1e-3, 1e-3 * p.length);
    int skipped = 0, made = 0;
    for (double s = 0.5 * p.spacing; s <= face_length; s += p.spacing) {
      const Vec2 head = p.face_from + (s / face_length) * along + inset * p.direction;
      const Vec2 end = head + p.length * p.direction;
      const int a = block_at(cut, head), b = block_at(cut, end);
      const std::string name = p.name + " " + std::to_string(made + skipped + 1);
      if (a < 0 || b < 0) {
        throw InputError(model.source + ": bolt_patterns[" + std::to_string(k) + "]: bolt \"" +
                         name + "\" has its " + (a < 0 ? "head" : "far end") + " outside every block of the cut (at " +
                         input::format_number((a < 0 ? head : end).x()) + ", " +
                         input::format_number((a < 0 ? head : end).y()) + "): shorten the bolts or move the face");
      }
      const auto fixed = [&cut](int i) { return cut.fixed[static_cast<std::size_t>(i)]; };
      if (a == b || (fixed(a) && fixed(b))) {
        ++skipped;
        continue;
      }
      ++made;
      ordered_json bolt = {{"name", name},
                           {"from", {head.x(), head.y()}},
                           {"to", {end.x(), end.y()}},
                           {"stiffness", p.stiffness}};
      if (p.pretension > 0.0) bolt["pretension"] = p.pretension;
      if (p.yield_force) bolt["yield_force"] = *p.yield_force;
      if (p.rupture_extension) bolt["rupture_extension"] = *p.rupture_extension;
      bolts.push_back(bolt);
    }
    if (skipped > 0) {
      left_out.push_back(p.name + ": " + std::to_string(skipped) + " of " + std::to_string(made + skipped) +
                         " bolts left out (both ends in one block, or in fixed rock: nothing to hold)");
    }
  }
  return bolts;
}

}  // namespace

CutScene cut_scene(const Model& model, const CutModel& cut, const std::string& scene_path) {
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
  for (const auto& edges : cut.edge_joint_materials) {
    for (const std::string& n : edges) {
      if (!n.empty()) used.insert(n);
    }
  }
  for (const auto& edges : cut.edge_bridges) {
    for (const EdgeBridge& e : edges) {
      if (e.share > 0.0) used.insert(e.material);
    }
  }
  // A joint material drawn at random is the study's even where no edge of the cut takes it:
  // kept, so that the scene's random_strengths names only what it holds.
  if (settings.contains("random_strengths")) {
    for (const char* list : {"variables", "correlations"}) {
      if (!settings.at("random_strengths").contains(list)) continue;
      for (const auto& v : settings.at("random_strengths").at(list)) {
        if (v.is_object() && v.contains("joint_material") && v.at("joint_material").is_string())
          used.insert(v.at("joint_material").get<std::string>());
      }
    }
  }
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
    blocks.push_back(block_json(cut.cut.blocks[i], cut.materials[i], cut.fixed[i],
                                cut.edge_joint_materials[i], cut.edge_bridges[i]));
  }
  scene["blocks"] = blocks;
  ordered_json joints = ordered_json::array();
  for (const CutJoint& j : cut.joints) {
    joints.push_back({{"blocks", {j.a, j.b}}, {"material", j.joint_material}});
  }
  if (!joints.empty()) scene["joints"] = joints;
  // What the study needs beside the blocks, as the model gives it: the keys that place
  // something in the blocks are checked when dda cut reads the scene back, the others (base
  // shaking, stages: e.g. the static consolidation dda fos starts from) were checked by the
  // model reader as a scene's.
  for (std::string_view key : kKeysInBlocks) {
    const std::string name(key);
    if (settings.contains(name)) scene[name] = ordered_json(settings.at(name));
  }
  if (!model.bolt_patterns.empty()) {
    // The patterns' bolts after those the model lists one by one.
    ordered_json bolts = scene.contains("bolts") ? scene["bolts"] : ordered_json::array();
    for (const ordered_json& b : pattern_bolts(model, cut, out.bolts_left_out)) bolts.push_back(b);
    if (!bolts.empty()) scene["bolts"] = bolts;
  }
  if (scene.contains("bolts") && scene["bolts"].is_array()) {
    const auto point = [](const ordered_json& p) {
      return p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number()
                 ? std::optional<Vec2>(Vec2(p[0].get<double>(), p[1].get<double>()))
                 : std::nullopt;
    };
    for (const ordered_json& b : scene["bolts"]) {
      if (!b.is_object() || !b.contains("from") || !b.contains("to")) continue;  // the read-back says why
      const std::optional<Vec2> from = point(b["from"]), to = point(b["to"]);
      if (from && to) out.bolt_lines.emplace_back(*from, *to);
    }
  }
  if (settings.contains("base_motion")) {
    ordered_json motion = ordered_json(settings.at("base_motion"));
    if (!scene_path.empty() && motion.contains("record") && motion["record"].is_string()) {
      // The scene reader reads a record relative to the scene's directory, the model's
      // relative to the model's: the same file, named from where the scene is.
      const fs::path record(motion["record"].get<std::string>());
      if (record.is_relative()) {
        const fs::path file = fs::absolute(fs::path(model.source).parent_path() / record);
        const fs::path scene_dir = fs::absolute(fs::path(scene_path)).parent_path();
        motion["record"] = file.lexically_normal().lexically_relative(scene_dir.lexically_normal()).string();
      }
    }
    scene["base_motion"] = motion;
  }
  if (settings.contains("random_strengths")) scene["random_strengths"] = ordered_json(settings.at("random_strengths"));
  if (settings.contains("stages")) {
    ordered_json stages = ordered_json(settings.at("stages"));
    // A stage's excavate_region: the blocks whose interior point (as regions place blocks)
    // lies in it, not removed by an earlier stage, as the scene stage's "excavate".
    std::vector<bool> removed(cut.cut.blocks.size(), false);
    const double tol = label_tolerance(model.spec.domain);
    for (std::size_t k = 0; k < model.stage_excavations.size() && k < stages.size(); ++k) {
      if (!model.stage_excavations[k]) continue;
      ordered_json list = ordered_json::array();
      for (std::size_t i = 0; i < cut.cut.blocks.size(); ++i) {
        if (removed[i]) continue;
        if (contains_point(*model.stage_excavations[k], interior_point(cut.cut.blocks[i], tol))) {
          removed[i] = true;
          list.push_back(static_cast<int>(i));
        }
      }
      if (list.empty()) {
        throw InputError(model.source + ": stages[" + std::to_string(k) +
                         "].excavate_region: holds no block of the cut (not removed by an earlier stage)");
      }
      stages[k]["excavate"] = list;
    }
    scene["stages"] = stages;
  }
  return out;
}

std::string scene_text(const ordered_json& scene) { return layout(scene, "") + "\n"; }

Scene read_back_cut_scene(const std::string& text, const std::string& scene_name,
                          const std::string& model_source) {
  try {
    Scene scene = parse_scene_text(text, scene_name);
    if (!scene.warnings.empty()) throw InputError(scene.warnings.front());
    return scene;
  } catch (const InputError& e) {
    const std::string what = e.what();
    const std::string prefix = scene_name + ": ";
    if (what.rfind(prefix, 0) == 0) {
      const std::string place = what.substr(prefix.size());
      for (std::string_view key : kKeysInBlocks) {
        if (place.rfind(std::string(key), 0) == 0) {
          throw InputError(model_source + ": " + place + " (on the blocks of the cut)");
        }
      }
    }
    throw InputError(model_source + ": the cut gives a scene that dda run does not accept as it "
                     "is (" + what + "); a larger min_block_area may help");
  }
}

}  // namespace dda
