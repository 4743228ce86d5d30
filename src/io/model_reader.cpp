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

constexpr std::string_view kSceneKeys[] = {"description",     "gravity", "plane",      "control",
                                           "materials",       "joint_materials", "stages",
                                           "base_motion",     "random_strengths"};

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
// both). The block is a unit triangle of the first material; only the names are used. The
// keys that place things in the blocks (kKeysInBlocks) are kept too, for the cut's scene,
// and checked there, on the cut's blocks (dda cut reads its scene back).
Scene read_scene_settings(const Field& root, const std::string& source,
                          nlohmann::json& settings,
                          std::vector<std::optional<Polygon>>& stage_excavations) {
  settings = nlohmann::json::object();
  for (std::string_view key : kSceneKeys) {
    if (root.has(key)) settings[std::string(key)] = root.value().at(std::string(key));
  }
  // A model's stage removes blocks by region ("excavate_region"), since no block exists
  // before the cut: read here, left out of what the scene reader checks, and turned into
  // the scene stage's "excavate" by the cut (cut_scene).
  if (root.has("stages") && root.member("stages").value().is_array()) {
    const std::vector<Field> stages = root.member("stages").elements(0, "");
    for (std::size_t k = 0; k < stages.size(); ++k) {
      std::optional<Polygon> region;
      if (stages[k].value().is_object()) {
        if (stages[k].has("excavate")) {
          stages[k].place("excavate").fail("a model names no block (the cut numbers them); give "
                                           "\"excavate_region\": the polygon whose blocks the stage removes");
        }
        if (auto g = stages[k].optional_member("excavate_region")) {
          region = read_polygon(*g);
          settings["stages"][k].erase("excavate_region");
        }
      }
      stage_excavations.push_back(region);
    }
  }
  nlohmann::json probe = settings;
  for (std::string_view key : kKeysInBlocks) {
    if (root.has(key)) settings[std::string(key)] = root.value().at(std::string(key));
  }
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
                 "spacing_scatter", "joint_material", "bridge_material"});
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
  if (auto g = f.optional_member("bridge_material")) {
    if (!(t.bridge > 0.0)) {
      g->fail("needs \"trace_length\" and a \"bridge\" > 0: the rock bridges it gives a "
              "strength to are the intact parts between a line's traces");
    }
    set.bridge_material = known_name(*g, joint_materials, "joint material");
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

// A region: a polygon and a material for its blocks, a joint material for its joints, or
// both.
RegionModel read_region(const Field& f, const std::vector<std::string>& materials,
                        const std::vector<std::string>& joint_materials) {
  f.expect_keys({"polygon", "material", "joint_material"});
  RegionModel region;
  region.polygon = read_polygon(f.member("polygon"));
  if (!f.has("material") && !f.has("joint_material")) {
    f.fail("give \"material\" (of the blocks in the region), \"joint_material\" (of the joints "
           "in it), or both");
  }
  if (auto g = f.optional_member("material")) region.material = known_name(*g, materials, "material");
  if (auto g = f.optional_member("joint_material")) {
    region.joint_material = known_name(*g, joint_materials, "joint material");
  }
  return region;
}

FixedModel read_fixed(const Field& f, std::size_t domain_edges) {
  f.expect_keys({"edges", "polygon", "depth"});
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
  if (auto g = f.optional_member("depth")) {
    fixed.depth = positive_number(*g);
    if (fixed.edges.size() == domain_edges) {
      g->fail("every domain edge is in \"edges\": there is no free surface to measure the "
              "depth from");
    }
  }
  return fixed;
}

// A bolt pattern: a name, a face (two points whose segment lies on the domain's boundary, the
// rock on one side of it), a spacing that fits at least one bolt on it, a length, a dip in
// [0, 90] degrees below the horizontal (90 on a horizontal face: straight down), and a
// scene bolt's law.
BoltPattern read_bolt_pattern(const Field& f, const Polygon& domain,
                              const std::vector<BoltPattern>& earlier) {
  f.expect_keys({"name", "face", "spacing", "length", "dip", "stiffness", "pretension",
                 "yield_force", "rupture_extension"});
  BoltPattern p;
  std::vector<std::string> taken;
  for (const BoltPattern& e : earlier) taken.push_back(e.name);
  p.name = input::csv_name(f.member("name"), "bolt pattern", "bolts.csv", taken);
  const Field face = f.member("face");
  const std::vector<Field> ends = face.elements(2, "give the face as two points [[x1, y1], [x2, y2]]");
  if (ends.size() != 2) face.fail("give the face as two points [[x1, y1], [x2, y2]]");
  p.face_from = input::within_limit(ends[0], ends[0].vec2("[x, y]"), input::kLargestCoordinate, "m");
  p.face_to = input::within_limit(ends[1], ends[1].vec2("[x, y]"), input::kLargestCoordinate, "m");
  const Vec2 along = p.face_to - p.face_from;
  const double face_length = along.norm();
  if (!(face_length > 0.0)) face.fail("its two points are the same: a face needs a length");
  // The rock's side: the one of the face's two sides, at its middle, inside the domain.
  const Vec2 middle = 0.5 * (p.face_from + p.face_to);
  const Vec2 left = Vec2(-along.y(), along.x()) / face_length;
  const double probe = 1e-6 * face_length;
  const bool left_in = contains_point(domain, middle + probe * left);
  const bool right_in = contains_point(domain, middle - probe * left);
  if (left_in == right_in) {
    face.fail("is not on the domain's boundary (the rock must lie on one side of its middle "
              "and not on the other)");
  }
  const Vec2 into = left_in ? left : Vec2(-left);
  p.spacing = positive_number(f.member("spacing"));
  if (p.spacing > face_length) {
    f.member("spacing").fail("is " + format_number(p.spacing) + " m, longer than the face (" +
                             format_number(face_length) + " m): no bolt fits on it");
  }
  p.length = input::within_limit(f.member("length"), positive_number(f.member("length")),
                                 input::kLargestCoordinate, "m");
  const Field dip_field = f.member("dip");
  const double dip = input::number_in_range(dip_field, 0.0, false, 90.0, false, "[0, 90] degrees");
  const double d = dip * M_PI / 180.0;
  if (into.x() == 0.0) {
    if (dip != 90.0) {
      dip_field.fail("must be 90 on a horizontal face (the rock lies straight " +
                     std::string(into.y() < 0.0 ? "below" : "above") + " it)");
    }
    p.direction = Vec2(0.0, into.y() < 0.0 ? -1.0 : 1.0);
  } else {
    p.direction = Vec2((into.x() > 0.0 ? 1.0 : -1.0) * std::cos(d), -std::sin(d));
  }
  // (Along the face, to round-off, is not into it either.)
  if (p.direction.dot(into) <= 1e-9) {
    dip_field.fail("points the bolts out of the rock at this face (dip " + format_number(dip) +
                   " degrees below the horizontal, away from the face): give a dip that enters it");
  }
  p.stiffness = input::within_limit(f.member("stiffness"), positive_number(f.member("stiffness")),
                                    input::kLargestPenalty, "N/m");
  if (auto g = f.optional_member("yield_force")) {
    p.yield_force = input::within_limit(*g, positive_number(*g), input::kLargestForce, "N/m");
  }
  if (auto g = f.optional_member("pretension")) {
    p.pretension = input::within_limit(*g, non_negative_number(*g), input::kLargestForce, "N/m");
    if (p.yield_force && p.pretension > *p.yield_force) {
      g->fail("is " + format_number(p.pretension) + " N/m, above the pattern's yield_force (" +
              format_number(*p.yield_force) + " N/m)");
    }
  }
  if (auto g = f.optional_member("rupture_extension")) {
    p.rupture_extension = input::within_limit(*g, positive_number(*g), input::kLargestCoordinate, "m");
  }
  return p;
}

Model read_model(const Field& root, const std::string& source) {
  root.expect_keys({"description", "gravity", "plane", "control", "materials",
                    "joint_materials", "material", "domain", "joint_sets", "seed", "joints",
                    "regions", "fixed", "min_block_area", "stages", "base_motion", "pins",
                    "point_loads", "monitors", "bolts", "water", "bolt_patterns", "random_strengths"});
  Model model;
  model.source = source;
  const Scene settings =
      read_scene_settings(root, source, model.scene_settings, model.stage_excavations);
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
      spec.regions.push_back(read_region(r, materials, joint_materials));
    }
  }
  if (auto g = root.optional_member("fixed")) spec.fixed = read_fixed(*g, spec.domain.size());
  if (auto g = root.optional_member("min_block_area")) {
    spec.min_block_area = non_negative_number(*g);
  }
  if (auto patterns = root.optional_member("bolt_patterns")) {
    for (const Field& p : patterns->elements(0, "")) {
      model.bolt_patterns.push_back(read_bolt_pattern(p, spec.domain, model.bolt_patterns));
    }
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
