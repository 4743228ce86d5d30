// A parameter sweep (`dda sweep SWEEP.json --out DIR`, docs/sweep.md): one scene run many
// times, each variant with some of its values replaced. The file names the scene, the
// command each variant runs (fos) with its options, and the variants: a "grid" (every
// combination of the values listed for each place) or a "list" (each variant's values
// given). A place is a JSON pointer into the scene, "/joint_materials/default/friction_angle",
// and must already hold a value there (a sweep changes values, it adds none: a misspelt key
// is then an error, not a variant that differs in nothing).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dda {

// The options of `dda fos` a sweep's variants take (the command line's names with "_").
struct SweepFosOptions {
  int jobs = 1;
  double tolerance = 0.01;
  double consolidation_factor = 1.0;
  bool skip_limit_analysis = false;
  long samples = 0;
  std::uint64_t seed = 0;
  double at_factor = 0.0;
};

struct SweepSpec {
  std::string source;      // the sweep file, for messages
  std::string scene_path;  // as read: relative to the sweep file's folder
  std::string command;     // "fos"
  SweepFosOptions fos;
  std::vector<std::string> pointers;                    // the places, in column order
  std::vector<std::vector<nlohmann::json>> variants;    // per variant, a value per place
};

// Reads and checks a sweep file. Throws InputError naming the file and the place in it.
SweepSpec read_sweep_file(const std::string& path);
SweepSpec parse_sweep(const nlohmann::json& doc, const std::string& source);

// The scene of variant `v`: `scene` with the variant's values at their places. Throws
// InputError naming the sweep file, the variant and the pointer when a place is not in the
// scene.
nlohmann::json variant_scene(const nlohmann::json& scene, const SweepSpec& spec, std::size_t v);

// "variant-003": the variant's folder and scene name in DIR.
std::string variant_name(std::size_t v);

}  // namespace dda
