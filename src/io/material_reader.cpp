#include "io/material_reader.hpp"

#include <algorithm>
#include <charconv>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <vector>

#include "io/input_limits.hpp"
#include "materials/validate_material.hpp"

namespace dda::input {

namespace {

// Which model each key belongs to. The one table behind both the key check and its message.
struct ModelKey {
  std::string_view key;
  bool elastic;
  bool drucker_prager;
  bool mohr_coulomb;
};
constexpr ModelKey kModelKeys[] = {
    {"model", true, true, true},           {"density", true, true, true},
    {"young", true, true, true},           {"poisson", true, true, true},
    {"cohesion", false, true, true},       {"friction_angle", false, true, true},
    {"dilation_angle", false, true, true}, {"tensile_strength", false, false, true},
    {"hardening", false, true, true},      {"match", false, true, false},
};

bool belongs(const ModelKey& k, MaterialModel model) {
  switch (model) {
    case MaterialModel::Elastic:
      return k.elastic;
    case MaterialModel::DruckerPrager:
      return k.drucker_prager;
    case MaterialModel::MohrCoulomb:
      return k.mohr_coulomb;
  }
  return false;
}

constexpr MaterialModel kModels[] = {MaterialModel::Elastic, MaterialModel::DruckerPrager,
                                     MaterialModel::MohrCoulomb};

// Every key of the object must belong to `model`. Run after the check against the keys of
// all models, so a key met here is a real parameter given to the wrong model (a typo has
// already been reported as an unknown key with a suggestion).
void check_keys_of_model(const Field& f, MaterialModel model) {
  for (const auto& [key, value] : f.members()) {
    const auto* k = std::find_if(std::begin(kModelKeys), std::end(kModelKeys),
                                 [&](const ModelKey& m) { return m.key == key; });
    if (k == std::end(kModelKeys) || belongs(*k, model)) continue;
    std::string owners, own_keys;
    for (MaterialModel m : kModels) {
      if (belongs(*k, m))
        owners += (owners.empty() ? "\"" : " and \"") + std::string(model_name(m)) + "\"";
    }
    for (const ModelKey& m : kModelKeys) {
      if (belongs(m, model)) own_keys += (own_keys.empty() ? "" : ", ") + std::string(m.key);
    }
    value.fail("not a key of the \"" + std::string(model_name(model)) + "\" model (it belongs to " +
               owners + "; keys of \"" + std::string(model_name(model)) + "\": " + own_keys + ")");
  }
}

std::vector<HardeningPoint> read_hardening(const Field& f) {
  std::vector<HardeningPoint> table;
  for (const Field& row : f.elements(1,
                                     "give at least one [eps_p, cohesion] row, or leave "
                                     "\"hardening\" out for a constant cohesion")) {
    const Vec2 v = row.vec2("[eps_p, cohesion]");
    within_limit(row, v.y(), kLargestStress, "Pa", "the cohesion ");
    table.push_back({v.x(), v.y()});
  }
  return table;
}

// The place of a validate_material error: its key is a parameter ("friction_angle") or a
// row of the hardening table ("hardening[2]").
Field place_of(const Field& material, const std::string& key) {
  const std::size_t bracket = key.find('[');
  if (bracket == std::string::npos) return material.place(key);
  const Field table = material.place(key.substr(0, bracket));
  std::size_t index = 0;
  const char* first = key.data() + bracket + 1;
  const auto [end, ec] = std::from_chars(first, key.data() + key.size(), index);
  if (ec == std::errc() && table.is_list() && index < table.value().size()) {
    return table.elements(0, "")[index];
  }
  return table;  // not reached for the keys validate_material gives
}

}  // namespace

PlaneMode read_plane(const Field& f) {
  const std::string name = f.string();
  if (name == "strain") return PlaneMode::Strain;
  if (name == "stress") return PlaneMode::Stress;
  f.fail("unknown plane mode " + quoted_text(name) + " (known: " +
         quoted_list({"strain", "stress"}) + ")");
}

Material read_material(const std::string& name, const Field& f, PlaneMode plane) {
  // Keys first (against every model's keys, so a typo gets its suggestion), then the model,
  // then whether each key belongs to it.
  // ("rigid" is a key of every model, so it is not in kModelKeys; a plastic one refuses it.)
  f.expect_keys({"model", "density", "young", "poisson", "cohesion", "friction_angle",
                 "dilation_angle", "tensile_strength", "hardening", "match", "rigid"});
  const Field model_field = f.member("model");
  const std::string model_text = model_field.string();
  const std::optional<MaterialModel> model = parse_model(model_text);
  if (!model) model_field.fail(unknown_model(shown_text(model_text)).message);
  check_keys_of_model(f, *model);

  Material m;
  m.name = name;
  MaterialParameters& p = m.parameters;
  p.plane = plane;
  p.density = within_limit(f.member("density"), positive_number(f.member("density")),
                           kLargestDensity, "kg/m^3");
  p.young = within_limit(f.member("young"), positive_number(f.member("young")), kLargestStress, "Pa");
  // The bounds keep the elastic matrix positive definite (bulk and shear moduli positive).
  p.poisson = number_in_range(f.member("poisson"), -1.0, true, 0.5, true,
                              "greater than -1 and less than 0.5");
  if (p.poisson > kLargestPoisson) {
    f.member("poisson").fail(
        format_number(p.poisson) + " is beyond what this program computes with: at most " +
        format_number(kLargestPoisson) +
        " (nearer 0.5 the bulk modulus grows without bound, and impacts gain energy or steps "
        "stall in contact cuts; 0.499 is already nearly incompressible, lambda / mu = 499; see "
        "docs/scene-format.md, \"Limits\")");
  }
  // Types here; ranges and the rules between parameters are validate_material's.
  auto read_strength = [&f](FrictionalStrength& s) {
    s.cohesion = within_limit(f.member("cohesion"), f.member("cohesion").number(), kLargestStress, "Pa");
    s.friction_angle = f.member("friction_angle").number();
    // Default 0: no plastic dilation, the usual choice for soils and rock masses, where
    // associated flow (dilation = friction) overstates the volume increase at failure.
    if (auto g = f.optional_member("dilation_angle")) s.dilation_angle = g->number();
    if (auto g = f.optional_member("hardening")) s.hardening = read_hardening(*g);
  };
  switch (*model) {
    case MaterialModel::Elastic:
      p.model_parameters = ElasticOnly{};
      break;
    case MaterialModel::DruckerPrager: {
      DruckerPragerParameters dp;
      read_strength(dp);
      if (auto g = f.optional_member("match")) {
        const std::string match_text = g->string();
        const std::optional<DruckerPragerMatch> match = parse_match(match_text);
        if (!match) g->fail(unknown_match(shown_text(match_text)).message);
        dp.match = *match;
      }
      p.model_parameters = std::move(dp);
      break;
    }
    case MaterialModel::MohrCoulomb: {
      MohrCoulombParameters mc;
      read_strength(mc);
      if (auto g = f.optional_member("tensile_strength")) {
        mc.tensile_strength = within_limit(*g, g->number(), kLargestStress, "Pa");
      }
      p.model_parameters = std::move(mc);
      break;
    }
  }
  if (const std::optional<ParameterError> e = validate_material(p)) {
    place_of(f, e->key).fail(e->message);
  }
  if (auto g = f.optional_member("rigid")) {
    m.rigid = g->boolean();
    // A rigid block has no strain, so a yield surface would never be reached: asking for
    // both is a contradiction, not something to ignore silently.
    if (m.rigid && is_plastic(p.model())) {
      g->fail("a rigid material cannot be plastic (\"" + std::string(model_name(p.model())) +
              "\"): a rigid block has no strain to yield; use \"model\": \"elastic\"");
    }
  }
  return m;
}

}  // namespace dda::input
