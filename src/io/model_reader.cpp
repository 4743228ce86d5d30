// Model JSON -> Model. The format is documented in docs/model-format.md; keep the two in step.
// The keys a model shares with a scene (description, gravity, plane, control, materials,
// joint_materials) are checked by the scene reader itself, so that a model is accepted
// exactly when the scene cut from it would be, with the same messages at the same places.
#include "io/model_reader.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "io/input_limits.hpp"
#include "io/json_input.hpp"
#include "io/polygon_input.hpp"
#include "io/scene_reader.hpp"
#include "kinematics/polygon.hpp"

namespace dda {
namespace {

using input::Field;
using input::format_number;
using input::integer_at_least;
using input::non_negative_number;
using input::positive_number;
using input::read_polygon;

constexpr std::string_view kSceneKeys[] = {"description", "gravity", "plane",    "control",
                                           "materials",   "joint_materials", "stages"};

// Caps on the traces a set may draw, so that a spacing or trace length given in the wrong
// unit is an error at its key rather than a cut that runs out of memory. A cut of 100 000
// lines or a million traces is far beyond any slope study (a large one cuts ~2000 blocks).
constexpr long kMaxLinesPerSet = 100000;
constexpr long kMaxTracesPerSet = 1000000;
// And on the blocks the sets make together, estimated from their crossings: a cut takes
// about 3 kB a block and 30 s per 100 000 (docs/model-format.md, "Size, time and memory"),
// a run some 37 kB a block; 300 000 blocks is a gigabyte to cut and more than a run can take
// in a day.
constexpr double kMaxEstimatedBlocks = 300000.0;

// The crossings of the joint sets inside the domain, pair by pair: lines of spacings s_i,
// s_j at an angle t cross A |sin t| / (s_i s_j) times over an area A, times each set's share
// of its lines that is trace (trace_length / (trace_length + bridge)). About the number of
// blocks when there are two sets or more.
double estimated_crossings(const std::vector<JointSetModel>& sets, double area) {
  const auto persistence = [](const JointSetSpec& t) {
    return t.trace_length ? *t.trace_length / (*t.trace_length + t.bridge) : 1.0;
  };
  double crossings = 0.0;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const JointSetSpec& a = sets[i].traces;
    for (std::size_t j = i + 1; j < sets.size(); ++j) {
      const JointSetSpec& b = sets[j].traces;
      const double angle = (a.dip - b.dip) * M_PI / 180.0;
      crossings += area * std::abs(std::sin(angle)) * persistence(a) * persistence(b) /
                   (a.spacing * b.spacing);
    }
  }
  return crossings;
}

// The model's scene keys as a one-block scene, read by the scene reader under the model's
// name: an error in them is reported at its place in the model (the keys are top-level in
// both). The block is a unit triangle of the first material; only the names are used.
Scene read_scene_settings(const Field& root, const std::string& source,
                          nlohmann::json& settings) {
  settings = nlohmann::json::object();
  for (std::string_view key : kSceneKeys) {
    if (root.has(key)) settings[std::string(key)] = root.value().at(std::string(key));
  }
  nlohmann::json probe = settings;
  std::string first_material;
  if (root.has("materials") && root.member("materials").value().is_object() &&
      !root.member("materials").value().empty()) {
    first_material = root.member("materials").value().begin().key();
  }
  probe["blocks"] = nlohmann::json::array(
      {{{"vertices", {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}}}, {"material", first_material}}});
  return parse_scene_text(probe.dump(), source);
}

// The cut gives two or more blocks in general, so the "default" joint material is required,
// as a scene of two or more blocks requires it.
void check_default_joint(const Field& root) {
  const std::string why =
      "the cut's blocks touch, and the \"default\" joint material is used between every pair "
      "of blocks whose shared edge belongs to no joint of another joint material (e.g. "
      "{\"friction_angle\": 30, \"cohesion\": 0, \"tensile_strength\": 0})";
  if (!root.has("joint_materials")) {
    root.place("joint_materials").fail("required key is missing: " + why);
  }
  const Field given = root.member("joint_materials");
  if (!given.has("default")) given.place("default").fail("required key is missing: " + why);
}

// The name at `f`, which must be one of `names`; `kind` names the list in the message as the
// scene reader does ("unknown material ... (materials defined: ...)").
std::string known_name(const Field& f, const std::vector<std::string>& names,
                       const std::string& kind) {
  const std::string name = f.string();
  if (std::find(names.begin(), names.end(), name) != names.end()) return name;
  f.fail("unknown " + kind + " " + input::quoted_text(name) + " (" + kind +
         "s defined: " + input::quoted_name_list(names) + ")");
}

template <class Named>
std::vector<std::string> names_of(const std::vector<Named>& list) {
  std::vector<std::string> names;
  for (const Named& item : list) names.push_back(item.name);
  return names;
}

double diagonal_of(const Polygon& domain) {
  const Box box = bounding_box(domain);
  return (box.max - box.min).norm();
}

JointSetModel read_joint_set(const Field& f, const std::vector<std::string>& joint_materials,
                             double diagonal) {
  f.expect_keys({"dip", "spacing", "trace_length", "bridge", "offset", "dip_scatter",
                 "spacing_scatter", "joint_material"});
  JointSetModel set;
  JointSetSpec& t = set.traces;
  t.dip = f.member("dip").number();
  const Field spacing = f.member("spacing");
  t.spacing = positive_number(spacing);
  if (diagonal / t.spacing > static_cast<double>(kMaxLinesPerSet)) {
    spacing.fail("gives about " + format_number(std::round(diagonal / t.spacing)) +
                 " lines across the domain (its bounding box's diagonal is " +
                 format_number(diagonal) + " m); at most " + std::to_string(kMaxLinesPerSet) +
                 " are allowed per set (is the spacing in metres?)");
  }
  if (auto g = f.optional_member("trace_length")) {
    t.trace_length = positive_number(*g);
  }
  if (auto g = f.optional_member("bridge")) {
    if (!t.trace_length) {
      g->fail("needs \"trace_length\": a rock bridge separates traces of a given length along "
              "a line; without \"trace_length\" every trace crosses the whole domain");
    }
    t.bridge = non_negative_number(*g);
  }
  if (t.trace_length) {
    const double traces =
        (diagonal / t.spacing + 2.0) * (diagonal / (*t.trace_length + t.bridge) + 1.0);
    if (traces > static_cast<double>(kMaxTracesPerSet)) {
      f.member("trace_length").fail("gives about " + format_number(std::round(traces)) +
                                    " traces over the domain; at most " +
                                    std::to_string(kMaxTracesPerSet) + " are allowed per set");
    }
  }
  if (auto g = f.optional_member("offset")) {
    t.offset = input::within_limit(*g, g->number(), input::kLargestCoordinate, "m");
  }
  if (auto g = f.optional_member("dip_scatter")) t.dip_scatter = non_negative_number(*g);
  if (auto g = f.optional_member("spacing_scatter")) t.spacing_scatter = non_negative_number(*g);
  if (auto g = f.optional_member("joint_material")) {
    set.joint_material = known_name(*g, joint_materials, "joint material");
  }
  return set;
}

SingleJointModel read_single_joint(const Field& f, const std::vector<std::string>& joint_materials,
                                   double diagonal) {
  f.expect_keys({"from", "to", "joint_material"});
  SingleJointModel joint;
  const Field from = f.member("from");
  joint.from = input::within_limit(from, from.vec2("[x, y]"), input::kLargestCoordinate, "m");
  const Field to = f.member("to");
  joint.to = input::within_limit(to, to.vec2("[x, y]"), input::kLargestCoordinate, "m");
  // Zero length at the domain's scale (the polygons' own degeneracy tolerance).
  if ((joint.to - joint.from).norm() <= 1e-12 * diagonal) {
    to.fail("is the same point as \"from\"; a joint is a segment of positive length");
  }
  if (auto g = f.optional_member("joint_material")) {
    joint.joint_material = known_name(*g, joint_materials, "joint material");
  }
  return joint;
}

RegionModel read_region(const Field& f, const std::vector<std::string>& materials) {
  f.expect_keys({"polygon", "material"});
  RegionModel region;
  region.polygon = read_polygon(f.member("polygon"));
  region.material = known_name(f.member("material"), materials, "material");
  return region;
}

FixedModel read_fixed(const Field& f, std::size_t domain_edges) {
  f.expect_keys({"edges", "polygon"});
  FixedModel fixed;
  if (auto edges = f.optional_member("edges")) {
    std::set<int> seen;
    for (const Field& e : edges->elements(0, "")) {
      const int i = e.integer();
      if (i < 0 || static_cast<std::size_t>(i) >= domain_edges) {
        e.fail("edge index " + std::to_string(i) + " is out of range (the domain has " +
               std::to_string(domain_edges) + " edges, numbered from 0 to " +
               std::to_string(domain_edges - 1) + "; edge i runs from vertex i to vertex i + 1)");
      }
      if (!seen.insert(i).second) e.fail("edge " + std::to_string(i) + " is listed twice");
      fixed.edges.push_back(i);
    }
  }
  if (auto g = f.optional_member("polygon")) fixed.polygon = read_polygon(*g);
  return fixed;
}

Model read_model(const Field& root, const std::string& source) {
  root.expect_keys({"description", "gravity", "plane", "control", "materials",
                    "joint_materials", "material", "domain", "joint_sets", "seed", "joints",
                    "regions", "fixed", "min_block_area", "stages"});
  Model model;
  model.source = source;
  const Scene settings = read_scene_settings(root, source, model.scene_settings);
  check_default_joint(root);
  const std::vector<std::string> materials = names_of(settings.materials);
  const std::vector<std::string> joint_materials = names_of(settings.joint_materials);

  ModelSpec& spec = model.spec;
  spec.domain = read_polygon(root.member("domain"));
  const double diagonal = diagonal_of(spec.domain);
  spec.material = known_name(root.member("material"), materials, "material");
  if (auto sets = root.optional_member("joint_sets")) {
    for (const Field& s : sets->elements(0, "")) {
      spec.joint_sets.push_back(read_joint_set(s, joint_materials, diagonal));
    }
    const double area = std::abs(signed_area(spec.domain));
    const double blocks = estimated_crossings(spec.joint_sets, area);
    if (blocks > kMaxEstimatedBlocks) {
      sets->fail("the sets cross about " + std::to_string(std::llround(blocks)) +
                 " times inside the domain (" + format_number(area) + " m^2): a cut into about "
                 "that many blocks; at most " + std::to_string(std::llround(kMaxEstimatedBlocks)) +
                 " are allowed (docs/model-format.md, \"Size, time and memory\"; is a spacing "
                 "in metres?)");
    }
  }
  if (auto g = root.optional_member("seed")) {
    spec.seed = static_cast<std::uint64_t>(integer_at_least(*g, 0));
  }
  if (auto joints = root.optional_member("joints")) {
    for (const Field& j : joints->elements(0, "")) {
      spec.joints.push_back(read_single_joint(j, joint_materials, diagonal));
    }
  }
  if (auto regions = root.optional_member("regions")) {
    for (const Field& r : regions->elements(0, "")) {
      spec.regions.push_back(read_region(r, materials));
    }
  }
  if (auto g = root.optional_member("fixed")) spec.fixed = read_fixed(*g, spec.domain.size());
  if (auto g = root.optional_member("min_block_area")) {
    spec.min_block_area = non_negative_number(*g);
  }
  return model;
}

}  // namespace

Model parse_model_text(const std::string& text, const std::string& source) {
  const nlohmann::json document = input::parse_strict_json(text, source);
  return read_model(Field(document, "", source), source);
}

Model read_model_file(const std::string& path) {
  return parse_model_text(input::read_input_file(path, "a model file"), path);
}

}  // namespace dda
