// Scene JSON -> Scene. The format is documented in docs/scene-format.md; keep the two in step.
// Every check happens here, once, so that the solver can trust a Scene without re-checking.
#include "io/scene_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <utility>
#include <variant>

#include "contact/broad_phase.hpp"
#include "io/input_limits.hpp"
#include "io/json_input.hpp"
#include "io/material_reader.hpp"
#include "io/polygon_input.hpp"
#include "io/random_strength_reader.hpp"
#include "kinematics/overlap.hpp"
#include "kinematics/polygon.hpp"
#include "materials/material.hpp"
#include "solver/rotation/treatment.hpp"

namespace dda {

namespace {

using input::Field;
using input::format_number;
using input::integer_at_least;
using input::non_negative_number;
using input::number_in_range;
using input::positive_number;
using input::read_polygon;
using input::within_limit;

// A duration (time step, stage, end time): positive and not below input::kSmallestDuration.
double duration(const Field& f) {
  return input::at_least(f, positive_number(f), input::kSmallestDuration, "s");
}

// A key that is not there but must be, when the rule is more than "always required" (so the
// message can say why). Reported at the key's place, like Field::member does.
[[noreturn]] void fail_missing(const Field& parent, std::string_view key, std::string_view why) {
  parent.place(key).fail("required key is missing: " + std::string(why));
}

// ---- top level and control ----

std::vector<double> read_time_steps(const Field& f) {
  if (!f.is_list()) return {duration(f)};
  std::vector<double> steps;
  for (const Field& step : f.elements(1, "a list of time steps must not be empty")) {
    steps.push_back(duration(step));
  }
  return steps;
}

// The run length is given one way only, so that the two can never disagree. With stages
// the run lasts the sum of their durations: "steps" would contradict it, and "end_time" may
// only repeat it (checked once the stages are read, check_staged_run_length).
void read_run_length(const Field& control, ControlSettings& c, bool staged) {
  if (staged) {
    if (control.has("steps")) {
      control.member("steps").fail(
          "not allowed with \"stages\": the run lasts the sum of the stages' durations; remove "
          "it (\"end_time\" may be given if it equals that sum)");
    }
    if (control.has("end_time")) c.end_time = duration(control.member("end_time"));
    return;
  }
  const bool has_steps = control.has("steps");
  const bool has_end_time = control.has("end_time");
  if (has_steps && has_end_time) {
    control.fail("give either \"steps\" or \"end_time\", not both");
  }
  if (!has_steps && !has_end_time) {
    control.fail("missing the run length: give \"steps\" (a number of steps) or \"end_time\" "
                 "(seconds)");
  }
  if (has_steps) c.steps = integer_at_least(control.member("steps"), 1);
  if (has_end_time) c.end_time = duration(control.member("end_time"));
}

// The value a name stands for in `table`, or one error naming `what` and the known names.
template <class E, std::size_t N>
E named_value(const Field& f, const EnumName<E> (&table)[N], const std::string& what) {
  const std::string name = f.string();
  if (const auto value = value_in(table, name)) return *value;
  f.fail("unknown " + what + " " + input::quoted_text(name) + " (known: " + quoted_names(table) +
         ")");
}

// The scene's names of the settings with two choices each (control.energy_losses,
// control.linear_solver, control.vtk_format): the choice is the value.
constexpr EnumName<bool> kEnergyLossNames[] = {{false, "report"}, {true, "stop"}};
constexpr EnumName<bool> kLinearSolverNames[] = {{true, "reuse"}, {false, "factorise"}};
constexpr EnumName<bool> kVtkFormatNames[] = {{true, "binary"}, {false, "ascii"}};

RotationUpdate read_rotation_update(const Field& f) {
  return named_value(f, kRotationUpdateNames, "rotation update");
}

// A positive number, or "auto" (nullopt); `unit` is shown in the message.
std::optional<double> positive_or_auto(const Field& f, std::string_view unit) {
  if (f.is_string()) {
    const std::string text = f.string();
    if (text == "auto") return std::nullopt;
    f.fail("expected a positive number (" + std::string(unit) + ") or \"auto\", got " +
           input::quoted_text(text));
  }
  return positive_number(f);
}

// `staged`: the scene has "stages", which set the run length (read_run_length).
ControlSettings read_control(const Field& f, bool staged) {
  f.expect_keys({"time_step", "steps", "end_time", "max_displacement_ratio",
                 "dynamic_coefficient", "rotation_update", "penalty", "output_every", "vtk_format",
                 "max_open_close", "max_augmentations", "allowed_penetration",
                 "energy_tolerance", "energy_losses", "linear_solver", "inertia",
                 "contact_solver"});
  ControlSettings c;
  c.time_steps = read_time_steps(f.member("time_step"));
  read_run_length(f, c, staged);
  if (auto g = f.optional_member("max_displacement_ratio")) {
    c.max_displacement_ratio =
        number_in_range(*g, 0.0, true, 1.0, false, "greater than 0 and at most 1");
  }
  if (auto g = f.optional_member("dynamic_coefficient")) {
    c.dynamic_coefficient = number_in_range(*g, 0.0, false, 1.0, false, "between 0 and 1");
  }
  if (auto g = f.optional_member("rotation_update")) {
    c.rotation_update = read_rotation_update(*g);
  }
  if (auto g = f.optional_member("penalty")) {
    c.penalty = positive_or_auto(*g, "N/m");
    if (c.penalty) within_limit(*g, *c.penalty, input::kLargestPenalty, "N/m");
  }
  if (auto g = f.optional_member("output_every")) c.output_every = integer_at_least(*g, 1);
  if (auto g = f.optional_member("vtk_format")) c.vtk_binary = named_value(*g, kVtkFormatNames, "vtk_format");
  // The open-close loop needs one iteration to change a contact's state and another to
  // confirm it, so fewer than 2 would cut every step in which a contact opens or closes.
  if (auto g = f.optional_member("max_open_close")) c.max_open_close = integer_at_least(*g, 2);
  if (auto g = f.optional_member("max_augmentations")) {
    // More rounds than 50 would only hide a load the penalty cannot carry.
    c.max_augmentations = integer_at_least(*g, 0);
    if (c.max_augmentations > 50) {
      g->fail("must be at most 50, got " + std::to_string(c.max_augmentations));
    }
  }
  if (auto g = f.optional_member("allowed_penetration")) {
    c.allowed_penetration = positive_or_auto(*g, "m");
  }
  if (auto g = f.optional_member("energy_tolerance")) c.energy_tolerance = positive_number(*g);
  if (auto g = f.optional_member("energy_losses")) {
    c.stop_on_energy_loss = named_value(*g, kEnergyLossNames, "energy_losses");
  }
  if (auto g = f.optional_member("linear_solver")) {
    c.reuse_factor = named_value(*g, kLinearSolverNames, "linear solver");
  }
  if (auto g = f.optional_member("contact_solver")) {
    c.contact_solver = named_value(*g, kContactSolverNames, "contact solver");
  }
  if (auto g = f.optional_member("inertia")) {
    const std::string name = g->string();
    if (name != "auto") {
      c.inertia = value_in(kInertiaNames, name);
      if (!c.inertia) {
        g->fail("unknown inertia " + input::quoted_text(name) + " (known: \"auto\", " +
                quoted_names(kInertiaNames) + ")");
      }
      if (*c.inertia == Inertia::PseudoRigid && !keeps_block_frame(c.rotation_update)) {
        g->fail("\"pseudo_rigid\" needs a rotation_update that keeps a block frame "
                "(\"local_frame\", \"local_frame_as_printed\" or \"finite_rotation\"), got \"" +
                std::string(rotation_update_name(c.rotation_update)) + "\"");
      }
    }
  }
  return c;
}

// ---- materials ----

// `plane` is the scene's: the plastic models are plane strain only.
std::vector<Material> read_materials(const Field& f, PlaneMode plane) {
  std::vector<Material> materials;
  for (const auto& [name, value] : f.members()) {
    materials.push_back(input::read_material(name, value, plane));
  }
  if (materials.empty()) f.fail("define at least one material");
  return materials;
}

// Index of the entry named by `f` in `list` (materials or joint materials); `kind` names the
// list in the message ("material" -> "unknown material ... (materials defined: ...)").
template <class Named>
int index_by_name(const Field& f, const std::vector<Named>& list, const std::string& kind) {
  const std::string name = f.string();
  std::vector<std::string> known;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i].name == name) return static_cast<int>(i);
    known.push_back(list[i].name);
  }
  f.fail("unknown " + kind + " " + input::quoted_text(name) + " (" + kind +
         "s defined: " + input::quoted_name_list(known) + ")");
}

int material_index(const Field& f, const std::vector<Material>& materials) {
  return index_by_name(f, materials, "material");
}

// ---- joint materials and joints ----

constexpr std::string_view kDefaultJoint = "default";

JointMaterial read_joint_material(const std::string& name, const Field& f) {
  f.expect_keys({"friction_angle", "cohesion", "tensile_strength", "law", "residual_friction_angle",
                 "residual_cohesion", "residual_slip", "jrc", "jcs"});
  JointMaterial j;
  j.name = name;
  if (auto g = f.optional_member("law")) {
    const std::string law = g->string();
    const std::optional<JointLawKind> kind = joint_law_of_name(law);
    if (!kind) {
      g->fail("unknown joint law " + input::quoted_text(law) +
              " (known: \"brittle_bond\", \"coulomb_slip\")");
    }
    j.law = *kind;
  }
  // 90 degrees would make tan(phi), the friction coefficient, infinite.
  j.friction_angle = number_in_range(f.member("friction_angle"), 0.0, false, 90.0, true,
                                     "at least 0 and less than 90 (degrees)");
  j.cohesion = within_limit(f.member("cohesion"), non_negative_number(f.member("cohesion")),
                            input::kLargestStress, "Pa");
  j.tensile_strength =
      within_limit(f.member("tensile_strength"), non_negative_number(f.member("tensile_strength")),
                   input::kLargestStress, "Pa");
  // Barton-Bandis: both or neither; friction_angle is then phi_r.
  if (f.has("jrc") != f.has("jcs")) {
    const char* missing = f.has("jrc") ? "jcs" : "jrc";
    f.place(missing).fail(std::string("required key is missing: a Barton-Bandis joint needs both "
                                      "\"jrc\" (the joint roughness coefficient, 0 to 20) and "
                                      "\"jcs\" (the joint wall compressive strength, Pa); "
                                      "without them the joint is Coulomb's"));
  }
  if (auto g = f.optional_member("jrc")) {
    j.jrc = number_in_range(*g, 0.0, false, 20.0, false, "at least 0 and at most 20");
    const Field jcs = f.member("jcs");
    j.jcs = within_limit(jcs, positive_number(jcs), input::kLargestStress, "Pa");
  }
  // Slip weakening: residual_slip (m) turns it on; the residual friction angle defaults to
  // the peak's and the residual cohesion to 0; neither may exceed its peak.
  const bool residual = f.has("residual_friction_angle") || f.has("residual_cohesion");
  if (residual && !f.has("residual_slip")) {
    f.place("residual_slip").fail("required key is missing: the slip (m) over which the joint "
                                  "falls from peak to residual");
  }
  if (auto g = f.optional_member("residual_slip")) {
    j.residual_slip = within_limit(*g, positive_number(*g), input::kLargestCoordinate, "m");
    j.residual_friction_angle = j.friction_angle;
    if (auto r = f.optional_member("residual_friction_angle")) {
      j.residual_friction_angle = number_in_range(*r, 0.0, false, j.friction_angle, false,
                                                  "at least 0 and at most the peak friction_angle (degrees)");
    }
    if (auto r = f.optional_member("residual_cohesion")) {
      j.residual_cohesion = number_in_range(*r, 0.0, false, j.cohesion, false,
                                            "at least 0 and at most the peak cohesion (Pa)");
    }
  }
  return j;
}

// "default" first (index 0, the joint of every pair not in "joints"), then the others in
// order of name (objects are read with their keys sorted, as for materials). Required with
// two or more blocks, so that the friction between blocks is always the user's choice; with
// one block the built-in frictionless default stays.
std::vector<JointMaterial> read_joint_materials(const Field& root, std::size_t block_count) {
  const bool required = block_count >= 2;
  const std::string why =
      "the scene has " + std::to_string(block_count) +
      " blocks, and the \"default\" joint material is used between every pair of blocks not "
      "named in \"joints\" (e.g. {\"friction_angle\": 30, \"cohesion\": 0, "
      "\"tensile_strength\": 0})";
  std::vector<JointMaterial> joints{kBuiltInDefaultJoint};
  const auto given = root.optional_member("joint_materials");
  if (!given) {
    if (required) fail_missing(root, "joint_materials", why);
    return joints;
  }
  const auto members = given->members();
  if (given->has(kDefaultJoint)) {
    joints.clear();
    joints.push_back(read_joint_material(std::string(kDefaultJoint),
                                         given->member(kDefaultJoint)));
  } else if (required) {
    fail_missing(*given, kDefaultJoint, why);
  }
  for (const auto& [name, value] : members) {
    if (name != kDefaultJoint) joints.push_back(read_joint_material(name, value));
  }
  return joints;
}

int joint_material_index(const Field& f, const std::vector<JointMaterial>& joint_materials) {
  return index_by_name(f, joint_materials, "joint material");
}

int block_index(const Field& f, std::size_t block_count) {
  const int i = f.integer();
  if (i < 0 || static_cast<std::size_t>(i) >= block_count) {
    f.fail("block index " + std::to_string(i) + " is out of range (the scene has " +
           std::to_string(block_count) + " blocks, numbered from 0 to " +
           std::to_string(block_count - 1) + ")");
  }
  return i;
}

std::vector<JointSpec> read_joints(const Field& f, std::size_t block_count,
                                   const std::vector<JointMaterial>& joint_materials) {
  std::vector<JointSpec> joints;
  std::map<std::pair<int, int>, std::string> seen;  // unordered pair -> place given first
  for (const Field& joint : f.elements(0, "")) {
    joint.expect_keys({"blocks", "material"});
    const Field pair = joint.member("blocks");
    const std::vector<Field> ends = pair.elements(2, "give the two blocks as [i, j]");
    if (ends.size() != 2) {
      pair.fail("expected a list of 2 block indices [i, j], got " + pair.describe());
    }
    JointSpec spec;
    spec.block_a = block_index(ends[0], block_count);
    spec.block_b = block_index(ends[1], block_count);
    if (spec.block_a == spec.block_b) {
      pair.fail("a joint is between two different blocks, got block " +
                std::to_string(spec.block_a) + " twice");
    }
    const auto key = std::minmax(spec.block_a, spec.block_b);
    const auto [first, inserted] = seen.emplace(key, pair.path());
    if (!inserted) {
      pair.fail("the pair of blocks " + std::to_string(key.first) + " and " +
                std::to_string(key.second) + " is already given in " + first->second +
                "; list each pair once");
    }
    spec.material = joint_material_index(joint.member("material"), joint_materials);
    joints.push_back(spec);
  }
  return joints;
}

// A list of one entry per edge of a block of `edge_count` edges (edge k from vertex k to
// vertex k + 1); `what` says what an entry is.
std::vector<Field> per_edge_entries(const Field& f, std::size_t edge_count, std::string_view what) {
  const std::vector<Field> entries = f.elements(1, "give one entry (" + std::string(what) + ") per edge");
  if (entries.size() != edge_count) {
    f.fail("expected one entry per edge (" + std::to_string(edge_count) +
           ", as the block has vertices), got " + std::to_string(entries.size()));
  }
  return entries;
}

// A block's "edge_joints": one entry per edge, a joint material's name or null (the edge lies
// on no joint: its contacts take their pair's material).
std::vector<int> read_edge_joints(const Field& f, std::size_t edge_count,
                                  const std::vector<JointMaterial>& joint_materials) {
  const std::vector<Field> entries = per_edge_entries(f, edge_count, "a joint material name or null");
  std::vector<int> edges;
  edges.reserve(entries.size());
  for (const Field& e : entries) {
    edges.push_back(e.value().is_null() ? -1 : joint_material_index(e, joint_materials));
  }
  return edges;
}

// A block's "edge_bridges": one entry per edge, null or {"material": name, "share": s}, the
// rock bridge smeared over that edge (0 < s <= 1 of its length).
std::vector<BlockSpec::EdgeBridge> read_edge_bridges(const Field& f, std::size_t edge_count,
                                                     const std::vector<JointMaterial>& joint_materials) {
  const std::vector<Field> entries =
      per_edge_entries(f, edge_count, "null or {\"material\": name, \"share\": s}");
  std::vector<BlockSpec::EdgeBridge> edges(entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const Field& e = entries[k];
    if (e.value().is_null()) continue;
    e.expect_keys({"material", "share"});
    edges[k].material = joint_material_index(e.member("material"), joint_materials);
    edges[k].share = number_in_range(e.member("share"), 0.0, true, 1.0, false,
                                     "greater than 0 and at most 1");
  }
  return edges;
}

// A joint material that no pair of blocks uses is likely a mistake (a pair left out of
// "joints", or a misspelt name there), but not one that stops the run.
std::vector<std::string> unused_joint_material_warnings(const Scene& scene,
                                                        const std::string& source) {
  std::vector<bool> used(scene.joint_materials.size(), false);
  used[0] = true;  // "default": every pair not in "joints"
  for (const JointSpec& j : scene.joints) used[j.material] = true;
  for (const BlockSpec& b : scene.blocks) {
    for (int m : b.edge_joints) {
      if (m >= 0) used[static_cast<std::size_t>(m)] = true;
    }
    for (const BlockSpec::EdgeBridge& e : b.edge_bridges) {
      if (e.material >= 0) used[static_cast<std::size_t>(e.material)] = true;
    }
  }
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (used[i]) continue;
    warnings.push_back(source + ": " +
                       input::member_path("joint_materials", scene.joint_materials[i].name) +
                       ": not used by any pair of blocks (name it in \"joints\")");
  }
  return warnings;
}

// A plastic material with friction but no dilation has no return for a stress beyond its
// apex (materials/return_mohr_coulomb.cpp, return_drucker_prager.cpp): a free block of it
// put in that much tension by an impact or a pull stops the run. Mohr-Coulomb's tension
// cut-off gives such stresses a return. Warned when a free block uses the material.
std::vector<std::string> apex_without_return_warnings(const Scene& scene, const std::string& source) {
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const MaterialParameters& p = scene.materials[i].parameters;
    const FrictionalStrength* f = frictional_strength(p);
    if (f == nullptr || f->friction_angle <= 0.0 || f->dilation_angle > 0.0) continue;
    const auto* mc = std::get_if<MohrCoulombParameters>(&p.model_parameters);
    if (mc != nullptr && mc->tensile_strength) continue;
    const bool used = std::any_of(scene.blocks.begin(), scene.blocks.end(), [i](const BlockSpec& b) {
      return !b.fixed && b.material == static_cast<int>(i);
    });
    if (!used) continue;
    const double apex = f->cohesion / std::tan(f->friction_angle * std::numbers::pi / 180.0);
    std::ostringstream text;
    text << source << ": " << input::member_path("materials", scene.materials[i].name) << ": "
         << (mc != nullptr ? "mohr_coulomb" : "drucker_prager")
         << " with dilation_angle 0" << (mc != nullptr ? " and no tensile_strength" : "")
         << " has no return for a stress beyond its apex (a mean tension of " << apex
         << " Pa, c cot phi): a block of it put in that much tension (an impact, a pull) can stop the run";
    text << (mc != nullptr ? "; a tension cut-off (tensile_strength, 0 for none) or a dilation angle gives such stresses a return"
                           : "; a dilation angle gives such stresses a return");
    warnings.push_back(text.str());
  }
  return warnings;
}

// ---- stages ----

// A stage's joint_materials: named joint materials of the scene, each with some of its
// properties replaced (the others stay the scene's).
std::vector<StageJoint> read_stage_joints(const Field& f,
                                          const std::vector<JointMaterial>& joint_materials) {
  std::vector<StageJoint> overrides;
  for (const auto& [name, value] : f.members()) {
    const auto it = std::find_if(joint_materials.begin(), joint_materials.end(),
                                 [&](const JointMaterial& j) { return j.name == name; });
    if (it == joint_materials.end()) {
      std::vector<std::string> known;
      for (const JointMaterial& j : joint_materials) known.push_back(j.name);
      value.fail("unknown joint material " + input::quoted_text(name) +
                 " (joint materials defined: " + input::quoted_name_list(known) +
                 "); a stage can only change the properties of the scene's joint materials");
    }
    value.expect_keys({"friction_angle", "cohesion", "tensile_strength"});
    if (value.members().empty()) {
      value.fail("give at least one of \"friction_angle\", \"cohesion\", \"tensile_strength\" "
                 "(the properties this stage replaces)");
    }
    StageJoint o;
    o.joint = static_cast<int>(it - joint_materials.begin());
    o.material = *it;
    // The same ranges as the scene's joint materials (read_joint_material).
    if (auto g = value.optional_member("friction_angle")) {
      o.material.friction_angle =
          number_in_range(*g, 0.0, false, 90.0, true, "at least 0 and less than 90 (degrees)");
    }
    if (auto g = value.optional_member("cohesion")) {
      o.material.cohesion = within_limit(*g, non_negative_number(*g), input::kLargestStress, "Pa");
    }
    if (auto g = value.optional_member("tensile_strength")) {
      o.material.tensile_strength =
          within_limit(*g, non_negative_number(*g), input::kLargestStress, "Pa");
    }
    overrides.push_back(o);
  }
  return overrides;
}

// One stage; what it leaves out is control's (`control`), or the scene's gravity (factor 1).
// `excavated`: per block, whether an earlier stage removed it (this stage's are added).
StageSpec read_stage(const Field& f, const ControlSettings& control,
                     const std::vector<JointMaterial>& joint_materials,
                     std::vector<bool>& excavated) {
  f.expect_keys({"duration", "dynamic_coefficient", "gravity_factor", "gravity_ramp",
                 "time_step", "joint_materials", "bond_closed_contacts", "excavate"});
  StageSpec s;
  s.duration = duration(f.member("duration"));
  s.dynamic_coefficient = control.dynamic_coefficient;
  if (auto g = f.optional_member("dynamic_coefficient")) {
    s.dynamic_coefficient = number_in_range(*g, 0.0, false, 1.0, false, "between 0 and 1");
  }
  if (f.has("gravity_factor") && f.has("gravity_ramp")) {
    f.fail("give either \"gravity_factor\" (a constant factor) or \"gravity_ramp\" ([from, to] "
           "over the stage), not both");
  }
  // A factor of gravity: at most input::kLargestAcceleration as a number, so that the factor
  // times the (bounded) gravity stays far from overflow.
  const auto factor = [](const Field& g) {
    return within_limit(g, non_negative_number(g), input::kLargestAcceleration, "");
  };
  if (auto g = f.optional_member("gravity_factor")) {
    s.gravity_from = s.gravity_to = factor(*g);
  }
  if (auto g = f.optional_member("gravity_ramp")) {
    g->vec2("[from, to]");  // the shape first, then each factor at its own place
    const std::vector<Field> ends = g->elements(2, "");
    s.gravity_from = factor(ends[0]);
    s.gravity_to = factor(ends[1]);
    s.gravity_ramp = true;
  }
  s.time_steps = control.time_steps;
  if (auto g = f.optional_member("time_step")) s.time_steps = read_time_steps(*g);
  if (auto g = f.optional_member("joint_materials")) {
    s.joint_materials = read_stage_joints(*g, joint_materials);
  }
  if (auto g = f.optional_member("bond_closed_contacts")) s.bond_closed_contacts = g->boolean();
  if (auto g = f.optional_member("excavate")) {
    const int blocks = static_cast<int>(excavated.size());
    for (const Field& e : g->elements(1, "list the indices of the blocks to remove")) {
      const int i = e.integer();
      if (i < 0 || i >= blocks) {
        e.fail("block " + std::to_string(i) + " is out of range (the scene has " +
               std::to_string(blocks) + " blocks, numbered from 0)");
      }
      if (excavated[static_cast<std::size_t>(i)]) {
        e.fail("block " + std::to_string(i) + " is excavated already (by this stage or an earlier one)");
      }
      excavated[static_cast<std::size_t>(i)] = true;
      s.excavate.push_back(i);
    }
  }
  return s;
}

// Durations summed as the run sums them (solver/stages.cpp), so that the last stage ends
// exactly at control.end_time.
double total_duration(const std::vector<StageSpec>& stages) {
  double total = 0.0;
  for (const StageSpec& s : stages) total += s.duration;
  return total;
}

// A given control.end_time must be the stages' total, up to 1e-9 of it: decimal durations
// do not add up exactly (0.1 + 0.2 is 0.30000000000000004), and the step loop takes times
// within 1e-9 of a step as equal too. The run then ends at the sum itself.
void check_staged_run_length(const Field& control, const std::vector<StageSpec>& stages,
                             ControlSettings& c) {
  const double total = total_duration(stages);
  if (c.end_time && std::abs(*c.end_time - total) > 1e-9 * total) {
    control.member("end_time").fail(
        "is " + format_number(*c.end_time) + " s, but the stages last " + format_number(total) +
        " s in all (the sum of their durations); leave \"end_time\" out or make the two agree");
  }
  c.end_time = total;
}

std::vector<StageSpec> read_stages(const Field& f, const ControlSettings& control,
                                   const std::vector<JointMaterial>& joint_materials,
                                   std::size_t block_count) {
  std::vector<StageSpec> stages;
  std::vector<bool> excavated(block_count, false);
  for (const Field& stage : f.elements(1, "list at least one stage, or leave \"stages\" out")) {
    stages.push_back(read_stage(stage, control, joint_materials, excavated));
  }
  return stages;
}

// ---- blocks, pins, loads ----

// A rigid block (its own "rigid", else its material's) has no strain, hence no stress and
// no yield: a plastic material or a non-zero initial stress contradicts it. (A rigid
// material is never plastic: material_reader refuses that at the material.)
void check_rigid_block(const Field& f, const BlockSpec& b, const Material& m) {
  if (!is_rigid(b, m)) return;
  const std::string why =
      b.rigid.has_value() ? "the block is rigid"
                          : "its material " + input::quoted_text(m.name) + " is rigid";
  if (is_plastic(m.parameters.model())) {
    f.member("rigid").fail("a rigid block cannot be of a plastic material (" +
                           input::quoted_text(m.name) +
                           "): it has no strain to yield; give it an elastic material");
  }
  if (b.initial_stress != Vec3::Zero()) {
    f.member("initial_stress").fail("must be [0, 0, 0] or left out: " + why +
                                    ", and a rigid block carries no stress");
  }
}

// A plastic block must start where its material can be: a stress outside the yield surface
// would be returned onto it at the first step, before any motion, with plastic strain from
// nowhere (Drucker-Prager), or leave the first step's Newton iteration nothing to converge
// to (Mohr-Coulomb). The same test as `dda material-point`'s (material_point_reader.cpp):
// a return at zero strain from the block's start state (szz = nu (sxx + syy), as
// make_world builds it) must stay elastic.
void check_plastic_start(const Field& f, const BlockSpec& b, const Material& m) {
  if (!is_plastic(m.parameters.model()) || b.fixed) return;
  const Vec3& s0 = b.initial_stress;
  const Vec4 start(s0[0], s0[1], m.parameters.poisson * (s0[0] + s0[1]), s0[2]);
  const MaterialResult r = integrate(m.parameters, MaterialState{}, Vec3::Zero(), start);
  const Field place = b.initial_stress == Vec3::Zero() ? f.member("material") : f.member("initial_stress");
  if (!r.status.converged) {
    place.fail("the material " + input::quoted_text(m.name) + " cannot start here: " +
               r.status.reason);
  }
  if (r.branch != Branch::Elastic) {
    place.fail("[" + format_number(s0[0]) + ", " + format_number(s0[1]) + ", " +
               format_number(s0[2]) + "] (with szz = poisson x (sxx + syy) = " +
               format_number(start[2]) + ") lies outside the yield surface of the material " +
               input::quoted_text(m.name) + " (a return at zero strain takes the \"" +
               std::string(branch_name(r.branch)) +
               "\" branch); start the block from a stress on or inside it");
  }
}

BlockSpec read_block(const Field& f, const std::vector<Material>& materials) {
  // "edge_joints" is read once the joint materials are (read_edge_joints).
  f.expect_keys({"vertices", "material", "fixed", "velocity", "initial_stress", "rigid", "edge_joints",
                 "edge_bridges"});
  BlockSpec b;
  b.vertices = read_polygon(f.member("vertices"));
  b.material = material_index(f.member("material"), materials);
  if (auto g = f.optional_member("fixed")) b.fixed = g->boolean();
  if (auto g = f.optional_member("velocity")) {
    b.velocity = within_limit(*g, g->vec3("[vx, vy, omega]"), input::kLargestSpeed, "m/s (rad/s)");
  }
  if (auto g = f.optional_member("initial_stress")) {
    b.initial_stress = within_limit(*g, g->vec3("[sxx, syy, sxy]"), input::kLargestStress, "Pa");
  }
  if (auto g = f.optional_member("rigid")) b.rigid = g->boolean();
  check_rigid_block(f, b, materials[static_cast<std::size_t>(b.material)]);
  check_plastic_start(f, b, materials[static_cast<std::size_t>(b.material)]);
  return b;
}

// Blocks may touch but not overlap at the start: an overlap is a contact penetrated far
// beyond anything the contact springs allow. A sweep over the blocks' bounding boxes
// (first_overlapping_pair) keeps this near-linear in the number of blocks and stops at the
// first overlapping pair it meets, reported at the later block of that pair in list order.
// (It used to list every pair of overlapping boxes first and then test them in list order:
// 5000 identical blocks took 2.9 s and 147 MB, 10 000 12 s and 545 MB, 100 000 ran out of
// memory, all to report blocks[1] and blocks[0].)
//
// Touching tolerance of a pair: 1e-9 of the larger block's bounding-box diagonal (scale-free;
// far below any real overlap, far above rounding in the distances, ~1e-16 relative), plus
// 1e-13 of the largest coordinate of the two, which covers the rounding of decimal input
// far from the origin (e.g. map coordinates in the millions of metres, where one unit in the
// last place is ~1e-9 m).
void check_no_overlap(const std::vector<Field>& fields, const std::vector<BlockSpec>& blocks) {
  std::vector<Box> boxes;
  std::vector<double> size, reach;  // per block: box diagonal, largest |coordinate|
  boxes.reserve(blocks.size());
  for (const BlockSpec& b : blocks) {
    const Box box = bounding_box(b.vertices);
    boxes.push_back(box);
    size.push_back((box.max - box.min).norm());
    reach.push_back(std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff()));
  }
  const auto found = first_overlapping_pair(boxes, [&](int i, int j) {
    const double tol = 1e-9 * std::max(size[i], size[j]) + 1e-13 * std::max(reach[i], reach[j]);
    return polygons_overlap(blocks[i].vertices, blocks[j].vertices, tol);
  });
  if (found) {
    const auto [i, j] = *found;
    fields[j].fail("overlaps blocks[" + std::to_string(i) +
                   "] at the start (blocks may touch but not overlap)");
  }
}

// Coordinates must be fine enough for the contacts: double precision spaces numbers near
// |x| = 1e15 m 0.125 m apart, so a block there cannot move by less (a free block at 1e15 m
// falls without moving) and a contact cannot resolve its penetration. Refused when the
// spacing at a vertex exceeds 1/1000 of the allowed penetration, so penetrations and step
// motions are resolved to at least a thousandth of that depth (map coordinates of 1e6 m
// are spaced 1.2e-10 m apart: a penetration down to 1.2e-7 m still passes).
constexpr double kCoordinateSpacingShare = 1e-3;

void check_coordinate_precision(const std::vector<Field>& fields,
                                const std::vector<BlockSpec>& blocks,
                                const ControlSettings& control) {
  std::vector<Polygon> polygons;
  for (const BlockSpec& b : blocks) polygons.push_back(b.vertices);
  const double allowed =
      control.allowed_penetration.value_or(kAutoPenetrationShare * scene_w0(polygons));
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    for (std::size_t k = 0; k < blocks[i].vertices.size(); ++k) {
      const double reach = blocks[i].vertices[k].cwiseAbs().maxCoeff();
      const double spacing = std::nextafter(reach, INFINITY) - reach;
      if (spacing <= kCoordinateSpacingShare * allowed) continue;
      fields[i].member("vertices").elements(0, "")[k].fail(
          "a coordinate of " + format_number(reach) + " m: double precision spaces numbers that "
          "large " + format_number(spacing) + " m apart, more than 1/1000 of the allowed "
          "penetration (" + format_number(allowed) + " m), so the blocks' motion and contacts "
          "would be lost in round-off; move the origin near the blocks (subtract a reference "
          "point from every coordinate) or raise control.allowed_penetration");
    }
  }
}

// The first block (in list order) containing the point; boundary points count as inside,
// so a pin on a shared edge goes to the block listed first.
int block_containing(const Field& point_field, const Vec2& p,
                     const std::vector<BlockSpec>& blocks) {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (contains_point(blocks[i].vertices, p)) return static_cast<int>(i);
  }
  point_field.fail("point (" + format_number(p.x()) + ", " + format_number(p.y()) +
                   ") is outside every block; it must lie inside or on the boundary of one");
}

PinSpec read_pin(const Field& f, const std::vector<BlockSpec>& blocks) {
  f.expect_keys({"point"});
  PinSpec pin;
  const Field point = f.member("point");
  pin.point = within_limit(point, point.vec2("[x, y]"), input::kLargestCoordinate, "m");
  pin.block = block_containing(point, pin.point, blocks);
  return pin;
}

PointLoadSpec read_point_load(const Field& f, const std::vector<BlockSpec>& blocks) {
  f.expect_keys({"point", "force"});
  PointLoadSpec load;
  const Field point = f.member("point");
  load.point = within_limit(point, point.vec2("[x, y]"), input::kLargestCoordinate, "m");
  load.force = within_limit(f.member("force"), f.member("force").vec2("[fx, fy]"),
                            input::kLargestForce, "N/m");
  load.block = block_containing(point, load.point, blocks);
  return load;
}

// A monitor: a unique non-empty name and a point inside (or on the boundary of) a block.
MonitorSpec read_monitor(const Field& f, const std::vector<BlockSpec>& blocks,
                         const std::vector<MonitorSpec>& earlier) {
  f.expect_keys({"name", "point"});
  MonitorSpec m;
  std::vector<std::string> taken;
  for (const MonitorSpec& e : earlier) taken.push_back(e.name);
  m.name = input::csv_name(f.member("name"), "monitor", "monitors.csv", taken);
  const Field point = f.member("point");
  m.point = within_limit(point, point.vec2("[x, y]"), input::kLargestCoordinate, "m");
  m.block = block_containing(point, m.point, blocks);
  return m;
}

// A bolt: a unique name, two points in two different blocks, not both fixed, an axial
// stiffness, and optionally a pretension, a yield force (at least the pretension) and a
// plastic extension at which it breaks (docs/scene-format.md, "bolts").
BoltSpec read_bolt(const Field& f, const std::vector<BlockSpec>& blocks,
                   const std::vector<BoltSpec>& earlier) {
  f.expect_keys({"name", "from", "to", "stiffness", "pretension", "yield_force",
                 "rupture_extension"});
  BoltSpec bolt;
  std::vector<std::string> taken;
  for (const BoltSpec& e : earlier) taken.push_back(e.name);
  bolt.name = input::csv_name(f.member("name"), "bolt", "bolts.csv", taken);
  const Field from = f.member("from");
  const Field to = f.member("to");
  bolt.from = within_limit(from, from.vec2("[x, y]"), input::kLargestCoordinate, "m");
  bolt.to = within_limit(to, to.vec2("[x, y]"), input::kLargestCoordinate, "m");
  if (!((bolt.to - bolt.from).norm() > 0.0)) to.fail("is the same point as \"from\": a bolt needs a length");
  bolt.block_from = block_containing(from, bolt.from, blocks);
  bolt.block_to = block_containing(to, bolt.to, blocks);
  if (bolt.block_from == bolt.block_to) {
    to.fail("lies in block " + std::to_string(bolt.block_to) + ", as \"from\" does: a bolt "
            "must join two blocks (anchor it in a fixed block for the ground)");
  }
  if (blocks[static_cast<std::size_t>(bolt.block_from)].fixed &&
      blocks[static_cast<std::size_t>(bolt.block_to)].fixed) {
    f.fail("joins two fixed blocks (" + std::to_string(bolt.block_from) + " and " +
           std::to_string(bolt.block_to) + "), which it cannot hold: put one end in a free block");
  }
  bolt.stiffness =
      within_limit(f.member("stiffness"), positive_number(f.member("stiffness")),
                   input::kLargestPenalty, "N/m");
  if (auto g = f.optional_member("yield_force")) {
    bolt.yield_force = within_limit(*g, positive_number(*g), input::kLargestForce, "N/m");
  }
  if (auto g = f.optional_member("pretension")) {
    bolt.pretension = within_limit(*g, non_negative_number(*g), input::kLargestForce, "N/m");
    if (bolt.pretension > bolt.yield_force) {
      g->fail("is " + format_number(bolt.pretension) + " N/m, above the bolt's yield_force (" +
              format_number(bolt.yield_force) + " N/m)");
    }
  }
  if (auto g = f.optional_member("rupture_extension")) {
    bolt.rupture_extension = within_limit(*g, positive_number(*g), input::kLargestCoordinate, "m");
  }
  return bolt;
}

// A water line: at least two points with x strictly increasing (it gives one water height per
// x). Its points are coordinates, bounded as the vertices are.
std::vector<Vec2> read_water_line(const Field& line, const char* what) {
  std::vector<Vec2> out;
  const std::vector<Field> points = line.elements(2, "list at least two points [x, y]");
  for (std::size_t i = 0; i < points.size(); ++i) {
    out.push_back(within_limit(points[i], points[i].vec2("[x, y]"), input::kLargestCoordinate, "m"));
    if (i > 0 && !(out[i].x() > out[i - 1].x())) {
      std::string why = "x must increase along the ";
      why += what;
      why += " (it gives one water height per x), got ";
      why += input::format_number(out[i].x());
      why += " after ";
      why += input::format_number(out[i - 1].x());
      points[i].fail(why);
    }
  }
  return out;
}

// The water table: a phreatic line, optionally a dry line and the share `fill` of the way
// from it up to the phreatic line, and the water's unit weight. The pressure it can put on a
// joint, unit weight x (the lines' highest point - the lowest vertex), is a stress (bounded
// as stresses are).
WaterTable read_water(const Field& f, const std::vector<BlockSpec>& blocks) {
  f.expect_keys({"phreatic_line", "unit_weight", "dry_line", "fill"});
  WaterTable water;
  water.phreatic_line = read_water_line(f.member("phreatic_line"), "phreatic line");
  if (auto dry = f.optional_member("dry_line")) water.dry_line = read_water_line(*dry, "dry line");
  if (auto fill = f.optional_member("fill")) {
    if (water.dry_line.empty()) {
      fill->fail("needs \"dry_line\": the fill is the share of the way from the dry line up to "
                 "the phreatic line");
    }
    water.fill = input::number_in_range(*fill, 0.0, false, 1.0, false, "in [0, 1]");
  }
  if (auto g = f.optional_member("unit_weight")) {
    water.unit_weight = within_limit(*g, positive_number(*g), input::kLargestUnitWeight, "N/m^3");
  }
  double top = -std::numeric_limits<double>::infinity();
  for (const Vec2& p : water.phreatic_line) top = std::max(top, p.y());
  for (const Vec2& p : water.dry_line) top = std::max(top, p.y());
  double bottom = top;
  for (const BlockSpec& b : blocks) {
    for (const Vec2& v : b.vertices) bottom = std::min(bottom, v.y());
  }
  const double pressure = water.unit_weight * (top - bottom);
  if (pressure > input::kLargestStress) {
    f.fail("the water pressure on the joints reaches up to " + format_number(pressure) +
           " Pa (unit weight " + format_number(water.unit_weight) + " N/m^3 x " +
           format_number(top - bottom) +
           " m from the lowest vertex up to the water lines' highest point), beyond what "
           "this program computes with: at most " + format_number(input::kLargestStress) +
           " Pa (see docs/scene-format.md, \"Limits\")");
  }
  return water;
}

// An acceleration record: a CSV file with the header "time,ax,ay" and one row per sample,
// times strictly increasing; read relative to the scene file's directory. Errors name the
// scene's place and the file's line.
void read_acceleration_record(const Field& f, const std::string& scene_source, double scale,
                              BaseMotion& motion) {
  const std::string name = f.string();
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(scene_source).parent_path() / path;
  std::string text;
  try {
    text = input::read_input_file(path.string(), "an acceleration record");
  } catch (const InputError& e) {
    f.fail(e.what());
  }
  std::istringstream in(text);
  std::string line;
  int line_number = 0;
  auto fail_line = [&](const std::string& what) {
    f.fail(path.string() + ", line " + std::to_string(line_number) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_number == 1) {
      if (line != "time,ax,ay") fail_line("the header must be \"time,ax,ay\", got " + input::quoted_text(line));
      continue;
    }
    if (line.empty()) continue;
    double v[3];
    std::istringstream row(line);
    for (int k = 0; k < 3; ++k) {
      std::string cell;
      if (!std::getline(row, cell, ',')) fail_line("expected 3 numbers (time, ax, ay)");
      char* end = nullptr;
      v[k] = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0' || !std::isfinite(v[k])) {
        fail_line(input::quoted_text(cell) + " is not a finite number");
      }
    }
    std::string extra;
    if (std::getline(row, extra, ',')) fail_line("expected 3 numbers (time, ax, ay), got more");
    if (!motion.times.empty() && !(v[0] > motion.times.back())) {
      fail_line("times must increase, got " + input::format_number(v[0]) + " after " +
                input::format_number(motion.times.back()));
    }
    const Vec2 a = scale * Vec2(v[1], v[2]);
    if (a.cwiseAbs().maxCoeff() > input::kLargestAcceleration) {
      fail_line("the acceleration (" + input::format_number(a.x()) + ", " +
                input::format_number(a.y()) + ") m/s^2, scale included, is beyond " +
                input::format_number(input::kLargestAcceleration) +
                " m/s^2 (see docs/scene-format.md, \"Limits\")");
    }
    motion.times.push_back(v[0]);
    motion.accelerations.push_back(a);
  }
  if (motion.times.size() < 2) f.fail(path.string() + ": a record needs at least two rows");
}

// The ground's motion: a sine or a record, from a start time.
BaseMotion read_base_motion(const Field& f, const std::string& source) {
  f.expect_keys({"start", "sine", "record", "scale"});
  BaseMotion m;
  if (auto g = f.optional_member("start")) m.start = non_negative_number(*g);
  const bool sine = f.has("sine"), record = f.has("record");
  if (sine == record) {
    f.fail("give exactly one of \"sine\" ({\"amplitude\": [ax, ay], \"frequency\": Hz, "
           "\"cycles\": n}) and \"record\" (a CSV file time,ax,ay)");
  }
  if (sine) {
    if (f.has("scale")) f.place("scale").fail("applies to a \"record\" only");
    const Field s = f.member("sine");
    s.expect_keys({"amplitude", "frequency", "cycles"});
    m.is_sine = true;
    m.amplitude = within_limit(s.member("amplitude"), s.member("amplitude").vec2("[ax, ay]"),
                               input::kLargestAcceleration, "m/s^2");
    m.frequency = positive_number(s.member("frequency"));
    if (auto c = s.optional_member("cycles")) m.cycles = positive_number(*c);
  } else {
    m.is_sine = false;
    double scale = 1.0;
    if (auto g = f.optional_member("scale")) scale = g->number();
    read_acceleration_record(f.member("record"), source, scale, m);
  }
  return m;
}

Scene read_scene(const Field& root, const std::string& source) {
  root.expect_keys({"description", "gravity", "plane", "control", "materials",
                    "joint_materials", "blocks", "joints", "pins", "point_loads", "monitors",
                    "bolts", "stages", "water", "base_motion", "random_strengths"});
  Scene scene;
  scene.source = source;
  if (auto g = root.optional_member("description")) g->string();  // free text, checked only
  if (auto g = root.optional_member("gravity")) {
    scene.gravity = within_limit(*g, g->vec2("[gx, gy]"), input::kLargestAcceleration, "m/s^2");
  }
  if (auto g = root.optional_member("plane")) scene.plane = input::read_plane(*g);
  const bool staged = root.has("stages");
  scene.control = read_control(root.member("control"), staged);
  scene.materials = read_materials(root.member("materials"), scene.plane);
  const std::vector<Field> block_fields =
      root.member("blocks").elements(1, "list at least one block");
  for (const Field& b : block_fields) {
    scene.blocks.push_back(read_block(b, scene.materials));
  }
  check_no_overlap(block_fields, scene.blocks);
  check_coordinate_precision(block_fields, scene.blocks, scene.control);
  scene.joint_materials = read_joint_materials(root, scene.blocks.size());
  if (auto joints = root.optional_member("joints")) {
    scene.joints = read_joints(*joints, scene.blocks.size(), scene.joint_materials);
  }
  for (std::size_t i = 0; i < block_fields.size(); ++i) {
    if (auto g = block_fields[i].optional_member("edge_joints")) {
      scene.blocks[i].edge_joints =
          read_edge_joints(*g, scene.blocks[i].vertices.size(), scene.joint_materials);
    }
    if (auto g = block_fields[i].optional_member("edge_bridges")) {
      scene.blocks[i].edge_bridges =
          read_edge_bridges(*g, scene.blocks[i].vertices.size(), scene.joint_materials);
    }
  }
  if (auto pins = root.optional_member("pins")) {
    for (const Field& p : pins->elements(0, "")) scene.pins.push_back(read_pin(p, scene.blocks));
  }
  if (auto loads = root.optional_member("point_loads")) {
    for (const Field& p : loads->elements(0, "")) {
      scene.point_loads.push_back(read_point_load(p, scene.blocks));
    }
  }
  if (auto monitors = root.optional_member("monitors")) {
    for (const Field& m : monitors->elements(0, "")) {
      scene.monitors.push_back(read_monitor(m, scene.blocks, scene.monitors));
    }
  }
  if (auto bolts = root.optional_member("bolts")) {
    for (const Field& b : bolts->elements(0, "")) {
      scene.bolts.push_back(read_bolt(b, scene.blocks, scene.bolts));
    }
  }
  if (auto water = root.optional_member("water")) scene.water = read_water(*water, scene.blocks);
  if (auto motion = root.optional_member("base_motion")) {
    scene.base_motion = read_base_motion(*motion, source);
  }
  if (staged) {
    scene.stages = read_stages(root.member("stages"), scene.control, scene.joint_materials,
                               scene.blocks.size());
    check_staged_run_length(root.member("control"), scene.stages, scene.control);
  }
  if (auto random = root.optional_member("random_strengths")) {
    scene.random_strengths = read_random_strengths(*random, scene.joint_materials, scene.materials, scene.water);
  }
  scene.warnings = unused_joint_material_warnings(scene, source);
  for (std::string& w : apex_without_return_warnings(scene, source)) scene.warnings.push_back(std::move(w));
  if (std::none_of(scene.blocks.begin(), scene.blocks.end(), [](const BlockSpec& b) { return !b.fixed; })) {
    scene.warnings.push_back(source + ": blocks: every block is fixed, so nothing will move (the "
                             "run takes its steps and writes its output unchanged)");
  }
  return scene;
}

}  // namespace

Scene parse_scene_text(const std::string& text, const std::string& source) {
  const nlohmann::json document = input::parse_strict_json(text, source);
  return read_scene(Field(document, "", source), source);
}

Scene read_scene_file(const std::string& path) {
  return parse_scene_text(input::read_input_file(path, "a scene file"), path);
}

}  // namespace dda
