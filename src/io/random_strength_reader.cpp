#include "io/random_strength_reader.hpp"

#include <cmath>
#include <initializer_list>
#include <string_view>
#include <limits>
#include <string>

#include "materials/material_types.hpp"
#include "studies/random_strengths.hpp"

namespace dda {
namespace {

using input::Field;
using input::format_number;

// A variable whose distribution reaches beyond the property's valid range by more than this
// (a friction angle below 0, a cohesion below 0) must say where to cut it: below it the
// rejection of such draws changes nothing a sample count could see.
constexpr double kLargestSilentTail = 1e-6;
// Bounds that keep less than this share of the distribution are a mistake (and would make
// drawing by rejection slow).
constexpr double kSmallestKept = 1e-3;

// The parts one after another (appending, not chains of operator+).
std::string join(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) out += p;
  return out;
}

// The owner's index: exactly one of "joint_material" and "material", naming one the scene
// defines.
template <class Named>
int owner_index(const Field& f, const std::vector<Named>& list, const char* kind) {
  const std::string name = f.string();
  std::vector<std::string> known;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i].name == name) return static_cast<int>(i);
    known.push_back(list[i].name);
  }
  f.fail(join({"unknown ", kind, " ", input::quoted_text(name), " (defined: ",
               input::quoted_name_list(known), ")"}));
}

struct Owner {
  StrengthOwner kind = StrengthOwner::JointMaterial;
  int index = 0;
  std::string name;
};

// The variable's owner: exactly one of "joint_material", "material" and (variables only:
// a correlation pairs two properties of one owner, and the water has one) "water".
Owner read_owner(const Field& f, const std::vector<JointMaterial>& joints,
                 const std::vector<Material>& materials, bool water_allowed) {
  const bool joint = f.has("joint_material"), block = f.has("material");
  const bool water = water_allowed && f.has("water");
  if (int(joint) + int(block) + int(water) != 1) {
    f.fail(water_allowed
               ? "give exactly one of \"joint_material\" (a joint material's name), \"material\" "
                 "(a plastic block material's name) and \"water\" (\"fill\": the water table's)"
               : "give exactly one of \"joint_material\" (a joint material's name) and "
                 "\"material\" (a plastic block material's name)");
  }
  Owner o;
  if (water) {
    o.kind = StrengthOwner::Water;
    o.name = "water";
  } else if (joint) {
    o.index = owner_index(f.member("joint_material"), joints, "joint material");
    o.name = joints[static_cast<std::size_t>(o.index)].name;
  } else {
    o.kind = StrengthOwner::Material;
    o.index = owner_index(f.member("material"), materials, "material");
    o.name = materials[static_cast<std::size_t>(o.index)].name;
  }
  return o;
}

StrengthProperty read_property(const Field& f, const Owner& o,
                               const std::vector<Material>& materials) {
  const std::string name = f.string();
  StrengthProperty p = StrengthProperty::FrictionAngle;
  if (name == "friction_angle") {
    p = StrengthProperty::FrictionAngle;
  } else if (name == "cohesion") {
    p = StrengthProperty::Cohesion;
  } else if (name == "tensile_strength") {
    p = StrengthProperty::TensileStrength;
  } else {
    f.fail(join({"unknown property ", input::quoted_text(name), " (known: ",
                 input::quoted_list({"friction_angle", "cohesion", "tensile_strength"}), ")"}));
  }
  if (o.kind == StrengthOwner::Material) {
    const MaterialParameters& m = materials[static_cast<std::size_t>(o.index)].parameters;
    const FrictionalStrength* s = frictional_strength(m);
    if (s == nullptr) {
      f.fail(join({"material ", input::quoted_text(o.name),
                   " is elastic: it has no strength to draw (only mohr_coulomb and "
                   "drucker_prager materials do)"}));
    }
    if (p == StrengthProperty::TensileStrength &&
        !std::holds_alternative<MohrCoulombParameters>(m.model_parameters)) {
      f.fail("only a mohr_coulomb material has a tensile_strength (a tension cut-off)");
    }
    if (p == StrengthProperty::Cohesion && !s->hardening.empty()) {
      f.fail(join({"material ", input::quoted_text(o.name),
                   " has a hardening curve, which fixes its cohesion; a drawn cohesion would "
                   "not match it"}));
    }
  }
  return p;
}

StrengthDistribution read_distribution(const Field& f) {
  const std::string name = f.string();
  if (name == "normal") return StrengthDistribution::Normal;
  if (name == "lognormal") return StrengthDistribution::Lognormal;
  f.fail(join({"unknown distribution ", input::quoted_text(name), " (known: ",
               input::quoted_list({"normal", "lognormal"}), ")"}));
}

// The property's valid range: a friction angle in [0, 90) degrees, a strength >= 0, a fill
// in [0, 1].
struct Range {
  double lo = 0.0;
  double hi = std::numeric_limits<double>::infinity();
  const char* text = "at least 0";
};
Range valid_range(StrengthProperty p) {
  if (p == StrengthProperty::FrictionAngle) {
    return {0.0, std::nextafter(90.0, 0.0), "at least 0 and below 90 (degrees)"};
  }
  if (p == StrengthProperty::WaterFill) return {0.0, 1.0, "in [0, 1]"};
  return {};
}

// "water": "fill", the water table's share of the way from its dry line to its phreatic line:
// the scene must have water with a dry line. The water has no other property to draw.
StrengthProperty read_water_property(const Field& f, const std::optional<WaterTable>& water) {
  if (f.string() != "fill") {
    f.fail(join({"unknown water property ", input::quoted_text(f.string()),
                 " (known: \"fill\", the share of the way from the dry line up to the phreatic "
                 "line)"}));
  }
  if (!water) f.fail("the scene has no \"water\" to fill");
  if (water->dry_line.empty()) {
    f.fail("the scene's \"water\" has no \"dry_line\": a drawn fill is the share of the way "
           "from it up to the phreatic line");
  }
  return StrengthProperty::WaterFill;
}

RandomStrength read_variable(const Field& f, const std::vector<JointMaterial>& joints,
                             const std::vector<Material>& materials,
                             const std::optional<WaterTable>& water) {
  f.expect_keys({"joint_material", "material", "water", "property", "distribution", "mean",
                 "standard_deviation", "min", "max"});
  const Owner o = read_owner(f, joints, materials, true);
  RandomStrength v;
  v.owner = o.kind;
  v.index = o.index;
  v.name = o.name;
  if (o.kind == StrengthOwner::Water) {
    if (f.has("property")) {
      f.member("property").fail("a water variable names its property in \"water\" (\"fill\")");
    }
    v.property = read_water_property(f.member("water"), water);
  } else {
    v.property = read_property(f.member("property"), o, materials);
  }
  v.distribution = read_distribution(f.member("distribution"));
  const Range valid = valid_range(v.property);
  const Field mean = f.member("mean");
  v.mean = v.distribution == StrengthDistribution::Lognormal
               ? input::positive_number(mean)
               : input::number_in_range(mean, valid.lo, false, valid.hi, false, valid.text);
  v.standard_deviation = input::positive_number(f.member("standard_deviation"));
  const std::optional<Field> min = f.optional_member("min");
  const std::optional<Field> max = f.optional_member("max");
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  if (min) lo = input::number_in_range(*min, valid.lo, false, valid.hi, false, valid.text);
  if (max) hi = input::number_in_range(*max, valid.lo, false, valid.hi, false, valid.text);
  if (min && max && !(hi > lo)) max->fail(join({"must be greater than min (", format_number(lo), ")"}));
  // What the distribution puts outside the valid range but inside the given bounds.
  const double below = probability_between(v, lo, valid.lo);
  const double above = probability_between(v, valid.hi, hi);
  const std::string what =
      join({strength_distribution_name(v.distribution), " ", strength_property_name(v.property),
            " of mean ", format_number(v.mean), " and standard deviation ",
            format_number(v.standard_deviation)});
  if (below > kLargestSilentTail) {
    (min ? *min : f).fail(join({"a ", what, " falls below ", format_number(valid.lo),
                                " with probability ", format_number(below),
                                ": give \"min\" (at least ", format_number(valid.lo),
                                ") to truncate it"}));
  }
  if (above > kLargestSilentTail) {
    const bool angle = v.property == StrengthProperty::FrictionAngle;
    (max ? *max : f).fail(join({"a ", what, angle ? " reaches 90 degrees" : " exceeds 1",
                                " with probability ", format_number(above), ": give \"max\" (",
                                angle ? "below 90" : "at most 1", ") to truncate it"}));
  }
  v.min = std::max(lo, valid.lo);
  v.max = std::min(hi, valid.hi);
  const double kept = probability_between(v, v.min, v.max);
  if (kept < kSmallestKept) {
    f.fail(join({"its bounds [", format_number(v.min), ", ", format_number(v.max), "] keep ",
                 format_number(kept), " of the ", what, " (at least ", format_number(kSmallestKept),
                 " is needed)"}));
  }
  return v;
}

StrengthCorrelation read_correlation(const Field& f, const RandomStrengths& out,
                                     const std::vector<JointMaterial>& joints,
                                     const std::vector<Material>& materials,
                                     std::vector<bool>& paired) {
  f.expect_keys({"joint_material", "material", "properties", "coefficient"});
  const Owner o = read_owner(f, joints, materials, false);
  const Field props = f.member("properties");
  const char* two = "must name two properties, e.g. [\"cohesion\", \"friction_angle\"]";
  const std::vector<Field> names = props.elements(2, two);
  if (names.size() != 2) props.fail(two);
  int index[2] = {-1, -1};
  for (int k = 0; k < 2; ++k) {
    const StrengthProperty p = read_property(names[static_cast<std::size_t>(k)], o, materials);
    for (std::size_t i = 0; i < out.variables.size(); ++i) {
      const RandomStrength& v = out.variables[i];
      if (v.owner == o.kind && v.index == o.index && v.property == p) index[k] = static_cast<int>(i);
    }
    if (index[k] < 0) {
      names[static_cast<std::size_t>(k)].fail(
          join({"is not one of the variables: a correlation pairs two properties of ",
                input::quoted_text(o.name), " that \"variables\" draws"}));
    }
    if (paired[static_cast<std::size_t>(index[k])]) {
      names[static_cast<std::size_t>(k)].fail("is already in a correlation (each variable may be in one)");
    }
  }
  if (index[0] == index[1]) props.fail("names the same property twice");
  StrengthCorrelation c;
  c.first = std::min(index[0], index[1]);
  c.second = std::max(index[0], index[1]);
  c.coefficient = input::number_in_range(f.member("coefficient"), -1.0, true, 1.0, true,
                                         "greater than -1 and less than 1");
  paired[static_cast<std::size_t>(c.first)] = true;
  paired[static_cast<std::size_t>(c.second)] = true;
  return c;
}

}  // namespace

RandomStrengths read_random_strengths(const Field& f, const std::vector<JointMaterial>& joints,
                                      const std::vector<Material>& materials,
                                      const std::optional<WaterTable>& water) {
  f.expect_keys({"variables", "correlations"});
  RandomStrengths out;
  for (const Field& v : f.member("variables").elements(1, "list at least one variable")) {
    RandomStrength r = read_variable(v, joints, materials, water);
    for (const RandomStrength& other : out.variables) {
      if (other.owner == r.owner && other.index == r.index && other.property == r.property) {
        v.fail(join({"draws ", input::quoted_text(r.name), "'s ", strength_property_name(r.property),
                     " a second time"}));
      }
    }
    out.variables.push_back(std::move(r));
  }
  if (auto c = f.optional_member("correlations")) {
    std::vector<bool> paired(out.variables.size(), false);
    for (const Field& g : c->elements(0, "")) {
      out.correlations.push_back(read_correlation(g, out, joints, materials, paired));
    }
  }
  return out;
}

}  // namespace dda
