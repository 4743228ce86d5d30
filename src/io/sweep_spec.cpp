#include "io/sweep_spec.hpp"

#include <cstdio>
#include <filesystem>

#include "io/json_input.hpp"

namespace dda {
namespace {

using input::Field;

// The most variants a sweep may ask for: a grid's combinations grow as a product, and a
// typo (ten lists of ten) should be an error, not a billion runs.
constexpr std::size_t kMostVariants = 100000;

void check_pointer(const Field& f, const std::string& text) {
  try {
    const nlohmann::json::json_pointer p(text);
    if (p.empty()) f.fail("the pointer \"\" is the whole scene; name a value in it");
  } catch (const nlohmann::json::exception&) {
    f.fail("not a JSON pointer (\"/joint_materials/default/friction_angle\"): " +
           input::quoted_text(text));
  }
}

// A variant's value: a number, a string, true or false (a list or an object would replace a
// whole part of the scene, which a sweep's columns cannot show).
nlohmann::json sweep_value(const Field& f) {
  const nlohmann::json& v = f.value();
  if (v.is_number()) return f.number();
  if (v.is_string() || v.is_boolean()) return v;
  f.fail("expected a number, a string or true/false, got " + f.describe());
}

SweepFosOptions fos_options(const Field& f) {
  f.expect_keys({"jobs", "tolerance", "consolidation_factor", "skip_limit_analysis", "samples",
                 "seed", "at_factor"});
  SweepFosOptions o;
  if (auto m = f.optional_member("jobs")) {
    o.jobs = input::integer_at_least(*m, 1);
    if (o.jobs > 64) m->fail("at most 64");
  }
  if (auto m = f.optional_member("tolerance")) {
    o.tolerance = input::number_in_range(*m, 1e-6, false, 1.0, false, "from 1e-6 to 1");
  }
  if (auto m = f.optional_member("consolidation_factor")) {
    o.consolidation_factor = input::number_in_range(*m, 1e-3, false, 1.0, false, "from 0.001 to 1");
  }
  if (auto m = f.optional_member("skip_limit_analysis")) o.skip_limit_analysis = m->boolean();
  if (auto m = f.optional_member("samples")) o.samples = input::integer_at_least(*m, 1);
  if (auto m = f.optional_member("seed")) o.seed = static_cast<std::uint64_t>(input::integer_at_least(*m, 0));
  if (auto m = f.optional_member("at_factor")) {
    o.at_factor = input::number_in_range(*m, 1e-3, false, 1e3, false, "from 0.001 to 1000");
    if (o.samples == 0) m->fail("judges each sample of \"samples\" at one F; give \"samples\"");
  }
  return o;
}

}  // namespace

SweepSpec parse_sweep(const nlohmann::json& doc, const std::string& source) {
  const Field root(doc, "", source);
  root.expect_keys({"description", "scene", "command", "fos", "grid", "list"});
  SweepSpec spec;
  spec.source = source;
  spec.scene_path = root.member("scene").string();
  if (spec.scene_path.empty()) root.member("scene").fail("empty; give the scene file's path");
  const Field command = root.member("command");
  spec.command = command.string();
  if (spec.command != "fos") command.fail("unknown command " + input::quoted_text(spec.command) + "; known: \"fos\"");
  if (auto f = root.optional_member("fos")) spec.fos = fos_options(*f);
  const bool grid = root.has("grid"), list = root.has("list");
  if (grid == list) root.fail("give the variants as \"grid\" or as \"list\" (one of them)");
  if (grid) {
    const Field g = root.member("grid");
    const auto places = g.members();
    if (places.empty()) g.fail("no place to vary; give \"/pointer\": [values]");
    spec.variants.emplace_back();
    for (const auto& [pointer, values] : places) {
      check_pointer(values, pointer);
      spec.pointers.push_back(pointer);
      std::vector<std::vector<nlohmann::json>> next;
      const std::vector<Field> listed = values.elements(1, "a value");
      if (spec.variants.size() * listed.size() > kMostVariants) {
        values.fail("the grid's combinations pass " + std::to_string(kMostVariants));
      }
      // The last place varies fastest: variants come in the grid's reading order.
      for (const auto& before : spec.variants) {
        for (const Field& v : listed) {
          next.push_back(before);
          next.back().push_back(sweep_value(v));
        }
      }
      spec.variants = std::move(next);
    }
  } else {
    const Field l = root.member("list");
    const std::vector<Field> rows = l.elements(1, "a variant");
    if (rows.size() > kMostVariants) l.fail("more than " + std::to_string(kMostVariants) + " variants");
    for (const auto& [pointer, value] : rows.front().members()) {
      check_pointer(value, pointer);
      spec.pointers.push_back(pointer);
    }
    if (spec.pointers.empty()) rows.front().fail("no place to vary; give {\"/pointer\": value}");
    for (const Field& row : rows) {
      const auto places = row.members();
      std::vector<nlohmann::json> values;
      for (std::size_t k = 0; k < places.size(); ++k) {
        if (k >= spec.pointers.size() || places[k].first != spec.pointers[k]) {
          row.fail("every variant gives the same places as the first (" +
                   input::quoted_text(spec.pointers.front()) + " ...)");
        }
        values.push_back(sweep_value(places[k].second));
      }
      if (values.size() != spec.pointers.size()) {
        row.fail("every variant gives the same places as the first (" +
                 std::to_string(spec.pointers.size()) + " of them)");
      }
      spec.variants.push_back(std::move(values));
    }
  }
  return spec;
}

SweepSpec read_sweep_file(const std::string& path) {
  const std::string text = input::read_input_file(path, "a sweep file");
  SweepSpec spec = parse_sweep(input::parse_strict_json(text, path), path);
  return spec;
}

nlohmann::json variant_scene(const nlohmann::json& scene, const SweepSpec& spec, std::size_t v) {
  nlohmann::json out = scene;
  for (std::size_t k = 0; k < spec.pointers.size(); ++k) {
    const nlohmann::json::json_pointer p(spec.pointers[k]);
    bool there = false;
    try {
      there = out.contains(p);
    } catch (const nlohmann::json::exception&) {
      there = false;  // a key into a list ("/blocks/x"): no such value either
    }
    if (!there) {
      throw InputError(spec.source + ": " + variant_name(v) + ": " +
                       input::quoted_text(spec.pointers[k]) +
                       " names no value of the scene " + spec.scene_path +
                       " (a sweep replaces values; it adds none)");
    }
    out[p] = spec.variants[v][k];
  }
  return out;
}

std::string variant_name(std::size_t v) {
  char name[32];
  std::snprintf(name, sizeof name, "variant-%03zu", v);
  return name;
}

}  // namespace dda
