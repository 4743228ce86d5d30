#include "app/cut_command.hpp"

#include "app/interrupt.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <vector>

#include "cutting/model.hpp"
#include "io/block_picture.hpp"
#include "io/cut_scene.hpp"
#include "io/output_file.hpp"
#include "io/text_file.hpp"
#include "io/json_input.hpp"
#include "io/model_reader.hpp"
#include "io/input_error.hpp"
#include "kinematics/polygon.hpp"

namespace dda {
namespace {

// Where the picture goes: SCENE.png beside SCENE.json.
std::string picture_path(const std::string& scene_path) {
  std::filesystem::path png(scene_path);
  png.replace_extension(".png");
  return png.string();
}

// The cut as a picture next to the scene (SCENE.png for SCENE.json): blocks coloured by
// material (in order of first appearance), fixed blocks grey, a legend of both.
std::string write_cut_picture(const CutModel& cut, const CutScene& scene,
                              const std::string& scene_path) {
  std::vector<std::string> names;
  std::vector<PictureBlock> blocks;
  constexpr Rgb kFixedGrey{190, 190, 190};
  for (std::size_t i = 0; i < cut.cut.blocks.size(); ++i) {
    auto it = std::find(names.begin(), names.end(), cut.materials[i]);
    if (it == names.end()) it = names.insert(names.end(), cut.materials[i]);
    const Rgb colour = category_colour(static_cast<int>(it - names.begin()));
    blocks.push_back({cut.cut.blocks[i], cut.fixed[i] ? kFixedGrey : colour});
  }
  PictureOptions options;
  options.width_px = 1600;
  options.axes = true;  // metres and a scale bar: the joint spacing reads off the picture
  options.title = std::to_string(blocks.size()) + " blocks cut from " + scene_path;
  for (std::size_t k = 0; k < names.size(); ++k) {
    options.legend.push_back({names[k], category_colour(static_cast<int>(k))});
  }
  if (std::find(cut.fixed.begin(), cut.fixed.end(), true) != cut.fixed.end()) {
    options.legend.push_back({"fixed", kFixedGrey});
  }
  for (const auto& [from, to] : scene.bolt_lines) options.lines.push_back({from, to});
  if (!scene.bolt_lines.empty()) options.legend.push_back({"bolts", PictureLine{}.colour});
  const std::string png = picture_path(scene_path);
  write_block_picture(png, blocks, options);
  return png;
}

// "rock 1900, weak 87" from the count of each name.
std::string counts_text(const std::map<std::string, int>& counts) {
  std::string text;
  for (const auto& [name, count] : counts) {
    text += (text.empty() ? "" : ", ") + input::shown_text(name) + " " + std::to_string(count);
  }
  return text;
}

// A warning when the model has joint sets and faces (domain edges not fixed that look up and
// sideways) but no set daylights in any face (daylights_in_face): planar sliding, the
// mechanism most rock-slope studies look for, is then impossible along a set (a floor of
// bedding at the toe's level, or bedding dipping into the slope, locked a slope at F 2.83).
void print_daylighting_warning(const ModelSpec& spec) {
  if (spec.joint_sets.empty()) return;
  const Polygon& d = spec.domain;
  std::vector<int> faces;
  bool any = false;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (is_fixed_edge(spec, i)) continue;
    const Vec2& p = d[i];
    const Vec2& q = d[(i + 1) % d.size()];
    const Vec2 edge = q - p;
    // Looking sideways, and up or level (outward normal (e_y, -e_x) of a counter-clockwise
    // domain): the slope's faces, a vertical cliff among them; a flat top, a floor or an
    // overhang is none.
    if (edge.x() > 0.0 || edge.y() == 0.0) continue;
    faces.push_back(static_cast<int>(i));
    for (const JointSetModel& s : spec.joint_sets) any = any || daylights_in_face(s.traces.dip, p, q);
  }
  if (faces.empty() || any) return;
  std::string list;
  for (int f : faces) list += (list.empty() ? "" : ", ") + std::to_string(f);
  std::cerr << "dda: cut: warning: no joint set daylights in the slope's faces (domain edges "
            << list << "): none dips out of a face less steeply than the face, so no block can "
               "slide out along a set's joints (docs/model-format.md, \"Daylighting\")\n";
}

void print_statistics(const Model& model, const CutModel& cut, const CutScene& scene,
                      const std::string& out_path) {
  const CutResult& c = cut.cut;
  double smallest = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < c.blocks.size(); ++i) {
    const double a = signed_area(c.blocks[i]);
    smallest = i == 0 ? a : std::min(smallest, a);
    largest = i == 0 ? a : std::max(largest, a);
  }
  std::map<std::string, int> by_material, by_joint;
  for (const std::string& m : cut.materials) ++by_material[m];
  const long fixed = std::count(cut.fixed.begin(), cut.fixed.end(), true);
  by_joint[kDefaultJointMaterial] = static_cast<int>(c.adjacency.size() - cut.joints.size());
  for (const CutJoint& j : cut.joints) ++by_joint[j.joint_material];
  using input::format_number;
  std::cerr << "dda: cut " << model.source << ": " << c.blocks.size() << " blocks; scene in "
            << out_path << "\n"
            << "dda: cut: " << c.dead_end_edges << " dead-end edges removed, " << c.holes_bridged
            << " holes bridged, " << c.slivers_merged << " slivers merged"
            << (c.collapsed_faces > 0
                    ? ", " + std::to_string(c.collapsed_faces) + " faces without area left out"
                    : std::string())
            << "\n"
            << "dda: cut: block area from " << format_number(smallest) << " to "
            << format_number(largest) << " m^2\n"
            << "dda: cut: blocks by material: " << counts_text(by_material) << "\n"
            << "dda: cut: " << fixed << " fixed blocks\n"
            << "dda: cut: pairs of touching blocks by joint material: " << counts_text(by_joint)
            << "\n";
  for (const std::string& name : scene.unused_joint_materials) {
    std::cerr << "dda: cut: joint material \"" << name
              << "\" left out of the scene: no pair of blocks shares an edge of its joints\n";
  }
  for (const std::string& line : scene.bolts_left_out) std::cerr << "dda: cut: bolt pattern " << line << "\n";
  print_daylighting_warning(model.spec);
}

// SIGINT or SIGTERM before the cut or while the scene is written: it stops at the next
// stage, before the scene is written (nothing is), or after it (no picture). During the
// cut itself the program ends at once (exit_at_once_on_interrupt).
int stopped(const std::string& what) {
  std::cerr << "dda: cut interrupted (signal " << interrupt_signal() << "); " << what << "\n";
  return interrupted_exit_code();
}

}  // namespace

int cut_command(const std::string& model_path, const std::string& out_path) {
  if (model_path.empty()) {
    throw InputError("cut: no model file given (dda cut MODEL.json --out SCENE.json; see "
                     "docs/model-format.md)");
  }
  const Model model = read_model_file(model_path);
  // The outputs' places before the cut: a directory, a block device or a socket there is
  // refused. A scene written into a character device or a FIFO (/dev/null, /dev/stdout)
  // gets no picture: there is no file beside it to put one.
  const bool scene_is_file = check_output_file(out_path) != OutputTarget::Stream;
  if (scene_is_file) check_output_file(picture_path(out_path));
  if (interrupt_signal() != 0) return stopped("nothing written");
  // The cut cannot stop inside CGAL's arrangement and has written nothing yet: a signal
  // ends it at once.
  exit_at_once_on_interrupt("dda: cut interrupted while cutting; nothing written\n");
  const CutModel cut = cut_model(model.spec);
  const CutScene scene = cut_scene(model, cut, out_path);
  const std::string text = scene_text(scene.scene);
  exit_at_once_on_interrupt(nullptr);
  write_text_file(out_path, text);
  // The scene is read back as `dda run` reads it: one it does not accept is the model's
  // error (with the scene left for inspection).
  read_back_cut_scene(text, out_path, model_path);
  print_statistics(model, cut, scene, out_path);
  if (!scene_is_file) {
    std::cerr << "dda: cut: no picture of the blocks: the scene went into " << out_path
              << ", which is not a regular file\n";
    return 0;
  }
  if (interrupt_signal() != 0) return stopped("the scene is in " + out_path + ", no picture drawn");
  const std::string picture = write_cut_picture(cut, scene, out_path);
  std::cerr << "dda: cut: picture of the blocks in " << picture << "\n";
  return 0;
}

}  // namespace dda
