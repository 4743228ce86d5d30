// The scene the command-line input tests edit, and a `dda run` of an edited copy of it
// (tests/app/test_input_limits_cli.cpp, test_hostile_inputs_cli.cpp).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_helpers.hpp"

namespace dda::test {

// A 1 m square resting on a fixed 10 m x 1 m floor: the scene each case edits.
inline nlohmann::json base_scene() {
  return nlohmann::json::parse(R"json({
    "control": {"time_step": 0.01, "steps": 3},
    "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
    "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
    "gravity": [0, -9.81],
    "blocks": [
      {"vertices": [[-5, -1], [5, -1], [5, 0], [-5, 0]], "material": "rock", "fixed": true},
      {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock"}
    ]
  })json");
}

struct SceneRun {
  CommandResult result;
  std::filesystem::path out;  // the run's --out directory
};

// Writes `scene` to DIR/NAME.json and runs `dda run` on it into DIR/out-NAME.
inline SceneRun run_scene(const TempDir& dir, const std::string& name, const nlohmann::json& scene) {
  const std::filesystem::path file = dir.path / (name + ".json");
  write_file(file, scene.dump());
  const std::filesystem::path out = dir.path / ("out-" + name);
  return {run_command(shell_quote(DDA_EXE) + " run " + shell_quote(file.string()) + " --out " +
                      shell_quote(out.string())),
          out};
}

}  // namespace dda::test
