// What the mutation fuzzer (verification/fuzz) found, each kept as a test through the real
// command line so that it stays found.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"
#include "support/cli_scenes.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

TEST_CASE("a step whose solve breaks down into nan is cut, never committed", "[input][cli]") {
  // A bar pinned near one end, released from the horizontal, with a cyclic time step of
  // 1 ms and 2000 s (a typing slip in a list): the 2000 s step (shortened to the end time,
  // 1.999 s) gave a nan answer, which the step-size check passed (std::max ignores a nan),
  // so the run exited 0 with nan in history.csv and the VTK files. Now a non-finite answer
  // is a motion too large for the step limit: the step is cut and the bar swings on.
  dda::test::TempDir dir("dda-fuzz-nan-");
  const json scene = json::parse(R"json({
    "gravity": [0.0, -9.81],
    "control": {"time_step": [0.001, 2000.0], "end_time": 2.0, "max_displacement_ratio": 0.01,
                "dynamic_coefficient": 1.0, "output_every": 20},
    "materials": {"rock": {"model": "elastic", "density": 2700.0, "young": 1e9, "poisson": 0.25}},
    "blocks": [{"vertices": [[0, 0], [1, 0], [1, 0.1], [0, 0.1]], "material": "rock"}],
    "pins": [{"point": [0.05, 0.05]}]
  })json");
  const dda::test::SceneRun run = dda::test::run_scene(dir, "bar", scene);
  INFO(run.result.output);
  REQUIRE(run.result.exit_code == 0);
  const std::vector<std::string> rows = dda::test::read_lines(run.out / "history.csv");
  REQUIRE(rows.size() > 2);
  int checked = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    REQUIRE_FALSE(dda::test::contains(rows[i], "nan"));
    REQUIRE_FALSE(dda::test::contains(rows[i], "inf"));
    // step,time,block,xc,yc,...: the centroid stays 0.45 m from the pin. The pin is a
    // penalty spring; its stretch under the swinging bar was measured at 1.5e-5 m, so
    // 1e-4 m says the pin held without hiding a bar thrown off its circle.
    std::stringstream fields(rows[i]);
    std::vector<double> v;
    for (std::string f; std::getline(fields, f, ',');) v.push_back(std::stod(f));
    REQUIRE(std::hypot(v[3] - 0.05, v[4] - 0.05) == Approx(0.45).margin(1e-4));
    ++checked;
  }
  const json summary = json::parse(dda::test::read_file(run.out / "summary.json"));
  CHECK(summary["cut_steps"].get<int>() > 0);  // the 2000 s steps were cut
  CHECK(checked > 10);
}

TEST_CASE("a block crushed through zero area stops the run naming it, with no nan written",
          "[input][cli]") {
  // A 1.2 m x 0.3 m pad of E = 1e-9 Pa (a mutated rubber) under a 0.8 m concrete block: the
  // pad has no stiffness to speak of and is crushed flat. Its area went through zero at
  // step 102, the polar decomposition of its inverted map gave nan, and the run stopped a
  // step later with nan in history.csv and the VTK files. Now a step that would turn a block
  // inside out is cut, and the run stops (exit 3) with a message that names the block and
  // says why, its last recorded state finite.
  dda::test::TempDir dir("dda-fuzz-crush-");
  const json scene = json::parse(R"json({
    "gravity": [0.0, -9.81],
    "control": {"time_step": 0.002, "end_time": 1.0, "output_every": 25},
    "materials": {"concrete": {"model": "elastic", "density": 2400, "young": 3e10, "poisson": 0.2,
                               "rigid": true},
                  "rubber": {"model": "elastic", "density": 1200, "young": 1e-9, "poisson": 0.45}},
    "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
    "blocks": [
      {"vertices": [[-2, -0.5], [2, -0.5], [2, 0], [-2, 0]], "material": "concrete", "fixed": true},
      {"vertices": [[-1.6, 0], [-0.4, 0], [-0.4, 0.3], [-1.6, 0.3]], "material": "rubber"},
      {"vertices": [[-1.4, 0.35], [-0.6, 0.35], [-0.6, 0.95], [-1.4, 0.95]], "material": "concrete"}
    ]
  })json");
  const dda::test::SceneRun run = dda::test::run_scene(dir, "crush", scene);
  INFO(run.result.output);
  CHECK(run.result.exit_code == 3);
  CHECK(dda::test::contains(run.result.output, "block 1 "));
  CHECK(dda::test::contains(run.result.output, "far too soft for its load"));
  const std::string history = dda::test::read_file(run.out / "history.csv");
  REQUIRE_FALSE(history.empty());
  CHECK_FALSE(dda::test::contains(history, "nan"));
  CHECK_FALSE(dda::test::contains(history, "inf"));
  for (const auto& e : fs::directory_iterator(run.out / "vtk")) {
    CHECK_FALSE(dda::test::contains(dda::test::read_file(e.path()), "nan"));
  }
}
