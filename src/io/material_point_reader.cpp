// Spec JSON -> MaterialPointSpec. The material object is read by the scene's own code
// (io/material_reader), so a scene material can be pasted into a spec unchanged.
#include "io/material_point_reader.hpp"

#include <array>
#include <optional>
#include <string_view>

#include "io/input_limits.hpp"
#include "io/json_input.hpp"
#include "io/material_reader.hpp"

namespace dda {

namespace {

using input::Field;
using input::format_number;

// The in-plane components in the order of PathSegment::targets (xx, yy, xy) and their names
// under each control.
constexpr std::array<std::string_view, 3> kStrainKeys = {"exx", "eyy", "gxy"};
constexpr std::array<std::string_view, 3> kStressKeys = {"sxx", "syy", "sxy"};

PathSegment read_segment(const Field& f) {
  f.expect_keys({"steps", "strain", "stress"});
  PathSegment segment;
  segment.steps = input::integer_at_least(f.member("steps"), 1);
  const std::optional<Field> strain = f.optional_member("strain");
  const std::optional<Field> stress = f.optional_member("stress");
  if (strain) strain->expect_keys({"exx", "eyy", "gxy"});
  if (stress) stress->expect_keys({"sxx", "syy", "sxy"});
  bool named = false;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::optional<Field> e = strain ? strain->optional_member(kStrainKeys[i]) : std::nullopt;
    const std::optional<Field> s = stress ? stress->optional_member(kStressKeys[i]) : std::nullopt;
    if (e && s) {
      // Reported at the stress key: it is read second, so it is the one that conflicts.
      s->fail("this component is also given in \"strain\" (" + std::string(kStrainKeys[i]) +
              "); control each in-plane component by strain or by stress, not both");
    }
    if (e) {
      segment.targets[i] = ComponentTarget{
          Control::Strain, input::within_limit(*e, e->number(), input::kLargestStrain, "")};
    }
    if (s) {
      segment.targets[i] = ComponentTarget{
          Control::Stress, input::within_limit(*s, s->number(), input::kLargestStress, "Pa")};
    }
    named = named || e || s;
  }
  // A segment that moves nothing would only repeat the last row (the models are rate
  // independent): more likely a mistake than a wish.
  if (!named) {
    f.fail(
        "names no component; give at least one target in \"strain\" (exx, eyy, gxy) or "
        "\"stress\" (sxx, syy, sxy)");
  }
  return segment;
}

// The start must be a state the material can be in: a stress outside the yield surface would
// be returned onto it at step 0, before any of the path, with plastic strain from nowhere.
void check_initial_stress(const Field& f, const MaterialPointSpec& spec) {
  if (spec.parameters().plane == PlaneMode::Stress && spec.initial_stress[kZZ] != 0.0) {
    f.fail("szz must be 0 in plane stress, got " + format_number(spec.initial_stress[kZZ]));
  }
  const MaterialResult at_start =
      integrate(spec.parameters(), MaterialState{}, Vec3::Zero(), spec.initial_stress);
  if (!at_start.status.converged)
    f.fail("the material cannot start here: " + at_start.status.reason);
  if (at_start.branch != Branch::Elastic) {
    f.fail(
        "lies outside the yield surface of the material (a return at zero strain takes the "
        "\"" +
        std::string(branch_name(at_start.branch)) +
        "\" branch); start from a stress on or inside it");
  }
}

MaterialPointSpec read_spec(const Field& root, const std::string& source) {
  root.expect_keys({"description", "material", "plane", "initial_stress", "path"});
  MaterialPointSpec spec;
  spec.source = source;
  if (auto g = root.optional_member("description")) g->string();  // free text, checked only
  PlaneMode plane = PlaneMode::Strain;
  if (auto g = root.optional_member("plane")) plane = input::read_plane(*g);
  spec.material = input::read_material("material", root.member("material"), plane);
  if (spec.material.rigid) {
    // The key belongs to scenes (blocks of the material get no strain); a point of a
    // rigid material would have no strain path to follow.
    root.member("material").member("rigid").fail(
        "a rigid material does not deform, so it has no stress-strain path to follow; leave "
        "\"rigid\" out of a material-point spec (it marks blocks rigid in a scene)");
  }
  if (auto g = root.optional_member("initial_stress")) {
    spec.initial_stress =
        input::within_limit(*g, g->vec4("[sxx, syy, szz, sxy]"), input::kLargestStress, "Pa");
    check_initial_stress(*g, spec);
  }
  for (const Field& segment : root.member("path").elements(1, "give at least one segment")) {
    spec.path.push_back(read_segment(segment));
  }
  return spec;
}

}  // namespace

MaterialPointSpec parse_material_point_text(const std::string& text, const std::string& source) {
  const nlohmann::json document = input::parse_strict_json(text, source);
  return read_spec(Field(document, "", source), source);
}

MaterialPointSpec read_material_point_file(const std::string& path) {
  return parse_material_point_text(input::read_input_file(path, "a material-point spec"), path);
}

}  // namespace dda
