// A model that carries the study (docs/model-format.md): pins, point loads, monitors, bolts,
// water, base shaking and stages copied into the cut's scene, and bolt patterns along a face
// turned into the scene's bolts; what does not fit the cut's blocks is the model's error at
// its place.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"
#include "cutting/model.hpp"
#include "io/cut_scene.hpp"
#include "support/input_refusal.hpp"
#include "io/model_reader.hpp"
#include "io/scene_reader.hpp"
#include "kinematics/polygon.hpp"

using namespace dda;
namespace fs = std::filesystem;
using dda::test::run_command;
using dda::test::shell_quote;

namespace {

// A 10 m square cut by horizontal bedding (y = 1.25, 3.75, 6.25, 8.75) and a vertical joint
// at x = 5: two columns of five rows. The bottom row (edge 0) and the rows above y = 8 are
// fixed. A row of bolts on the left face, every 2 m from y = 1, 7 m long, horizontal into the
// rock: the heads at y = 1, 3, 5, 7, 9 in the left column, the far ends in the right one.
nlohmann::json study_model() {
  return nlohmann::json::parse(R"({
    "control": {"time_step": 0.001},
    "materials": {"rock": {"model": "elastic", "density": 2600, "young": 1e9, "poisson": 0.25}},
    "joint_materials": {"default": {"friction_angle": 35, "cohesion": 0, "tensile_strength": 0}},
    "material": "rock",
    "domain": [[0, 0], [10, 0], [10, 10], [0, 10]],
    "joint_sets": [{"dip": 0, "spacing": 2.5, "offset": 1.25}],
    "joints": [{"from": [5, -1], "to": [5, 11]}],
    "fixed": {"edges": [0], "polygon": [[0, 8], [10, 8], [10, 11], [0, 11]]},
    "pins": [{"point": [7.5, 5.0]}],
    "point_loads": [{"point": [2.5, 5.0], "force": [1000.0, 0.0]}],
    "monitors": [{"name": "face", "point": [0.5, 5.0]}],
    "water": {"phreatic_line": [[0, 4], [10, 6]]},
    "stages": [{"duration": 0.005, "dynamic_coefficient": 0}],
    "bolts": [{"name": "single", "from": [2.5, 2.5], "to": [7.5, 2.5], "stiffness": 1e8}],
    "bolt_patterns": [{"name": "row", "face": [[0, 0], [0, 10]], "spacing": 2, "length": 7,
                       "dip": 0, "stiffness": 1e9, "pretension": 1e4, "yield_force": 1e5}]
  })");
}

std::string model_error(const nlohmann::json& model) {
  return test::refusal_of([&] {
    const Model m = parse_model_text(model.dump(), "model.json");
    cut_scene(m, cut_model(m.spec));
  });
}

}  // namespace

TEST_CASE("a model carries pins, loads, monitors, bolts, water and stages into its scene, which "
          "reads back with them",
          "[cut][model]") {
  const Model model = parse_model_text(study_model().dump(), "model.json");
  const CutModel cut = cut_model(model.spec);
  const CutScene out = cut_scene(model, cut);
  for (const char* key : {"pins", "point_loads", "monitors", "water", "stages", "bolts"}) {
    INFO(key);
    CHECK(out.scene.contains(key));
  }
  const Scene scene = parse_scene_text(scene_text(out.scene), "cut.json");
  CHECK(scene.warnings.empty());
  CHECK(scene.pins.size() == 1);
  CHECK(scene.point_loads.size() == 1);
  REQUIRE(scene.monitors.size() == 1);
  CHECK(scene.monitors[0].name == "face");
  CHECK(scene.water.has_value());
  CHECK(scene.stages.size() == 1);
  // The model's own bolt first, then the pattern's: heads at y = 3, 5, 7 join the left
  // column to the right one; those at y = 1 and 9 lie in fixed rows at both ends and are
  // left out, with a note.
  REQUIRE(scene.bolts.size() == 4);
  CHECK(scene.bolts[0].name == "single");
  const double heads[] = {3.0, 5.0, 7.0};
  for (int k = 0; k < 3; ++k) {
    const BoltSpec& b = scene.bolts[static_cast<std::size_t>(k + 1)];
    INFO("bolt " << b.name);
    CHECK(b.name == "row " + std::to_string(k + 2));
    // 1 mm inside the face along the bolt (a head on the face could round outside it).
    CHECK(b.from.x() == Approx(1e-3).margin(1e-12));
    CHECK(b.from.y() == Approx(heads[k]).margin(1e-12));
    CHECK(b.to.x() == Approx(7.001).margin(1e-12));
    CHECK(b.to.y() == Approx(heads[k]).margin(1e-12));
    CHECK(b.stiffness == 1e9);
    CHECK(b.pretension == 1e4);
    CHECK(b.yield_force == 1e5);
    CHECK(std::isinf(b.rupture_extension));
    CHECK(b.block_from != b.block_to);
  }
  REQUIRE(out.bolts_left_out.size() == 1);
  CHECK(out.bolts_left_out[0].find("2 of 5") != std::string::npos);
}

TEST_CASE("a bolt pattern is refused at its place", "[cut][model]") {
  struct Bad {
    const char* key;
    nlohmann::json value;
    std::string words;
  };
  const std::vector<Bad> bad = {
      {"face", {{2, 2}, {4, 4}}, "bolt_patterns[0].face: is not on the domain's boundary"},
      {"face", {{0, 0}, {0, 0}}, "bolt_patterns[0].face: its two points are the same"},
      {"spacing", 20.0, "bolt_patterns[0].spacing: is 20 m, longer than the face"},
      {"dip", 95.0, "bolt_patterns[0].dip"},
      {"dip", 90.0, "bolt_patterns[0].dip: points the bolts out of the rock"},
      {"pretension", 2e5, "bolt_patterns[0].pretension: is 2e+05 N/m, above the pattern's yield_force"},
      {"length", 30.0, "bolt_patterns[0]: bolt \"row 1\" has its far end outside every block"},
      {"stiffness", -1.0, "bolt_patterns[0].stiffness"},
  };
  for (const Bad& b : bad) {
    nlohmann::json model = study_model();
    model["bolt_patterns"][0][b.key] = b.value;
    const std::string message = model_error(model);
    INFO(message);
    CHECK(message.find("model.json: " + b.words) == 0);
  }
}

TEST_CASE("dda cut: a carried key that does not fit the cut's blocks is the model's error at its "
          "place, and a base_motion record is named from the scene's directory",
          "[cut][model]") {
  const dda::test::TempDir dir("dda_model_study_");
  nlohmann::json model = study_model();
  model["monitors"][0]["point"] = {20.0, 5.0};
  const fs::path model_path = dir.path / "model.json";
  std::ofstream(model_path) << model.dump();
  const test::CommandResult r = run_command(shell_quote(DDA_EXE) + " cut " +
                                            shell_quote(model_path.string()) + " --out " +
                                            shell_quote((dir.path / "scene.json").string()));
  CHECK(r.exit_code == 2);
  CHECK(r.output.find(model_path.string() + ": monitors[0].point: point (20, 5) is outside "
                      "every block") != std::string::npos);
  CHECK(r.output.find("(on the blocks of the cut)") != std::string::npos);

  // The record next to the model, the scene one directory down: "../quake.csv".
  model = study_model();
  std::ofstream(dir.path / "quake.csv") << "time,ax,ay\n0,0,0\n0.01,0.5,0\n";
  model["base_motion"] = {{"record", "quake.csv"}};
  std::ofstream(model_path) << model.dump();
  fs::create_directories(dir.path / "scenes");
  const fs::path scene_path = dir.path / "scenes" / "scene.json";
  const test::CommandResult ok = run_command(shell_quote(DDA_EXE) + " cut " +
                                             shell_quote(model_path.string()) + " --out " +
                                             shell_quote(scene_path.string()));
  INFO(ok.output);
  REQUIRE(ok.exit_code == 0);
  const nlohmann::json scene = nlohmann::json::parse(std::ifstream(scene_path));
  CHECK(scene["base_motion"]["record"] == "../quake.csv");
  CHECK(read_scene_file(scene_path.string()).base_motion.has_value());
}

TEST_CASE("a model's stage removes the blocks of its excavate_region: the cut's scene lists them",
          "[cut][model][excavation]") {
  nlohmann::json model = study_model();
  // The right column's cell between y = 6.25 and 8.75 (its interior point at (7.5, 7.5)).
  model["stages"].push_back({{"duration", 0.005},
                             {"dynamic_coefficient", 0},
                             {"excavate_region", {{5.5, 6.5}, {9.5, 6.5}, {9.5, 8.5}, {5.5, 8.5}}}});
  const Model m = parse_model_text(model.dump(), "model.json");
  const CutModel cut = cut_model(m.spec);
  const CutScene out = cut_scene(m, cut);
  REQUIRE(out.scene["stages"].size() == 2);
  CHECK_FALSE(out.scene["stages"][0].contains("excavate"));
  REQUIRE(out.scene["stages"][1]["excavate"].size() == 1);
  const int removed = out.scene["stages"][1]["excavate"][0].get<int>();
  const Polygon& block = cut.cut.blocks[static_cast<std::size_t>(removed)];
  const Vec2 c = polygon_moments(block).centroid;
  CHECK(c.x() == Approx(7.5));
  CHECK(c.y() == Approx(7.5));
  CHECK_FALSE(out.scene["stages"][1].contains("excavate_region"));
  const Scene scene = parse_scene_text(scene_text(out.scene), "cut.json");
  CHECK(scene.stages[1].excavate == std::vector<int>{removed});

  // A model names no block; a region holding none is refused at its place.
  nlohmann::json bad = model;
  bad["stages"][1]["excavate"] = {1};
  CHECK(model_error(bad).find("model.json: stages[1].excavate: a model names no block") == 0);
  bad = model;
  bad["stages"][1]["excavate_region"] = {{50, 50}, {60, 50}, {60, 60}};
  CHECK(model_error(bad).find("model.json: stages[1].excavate_region: holds no block of the cut") == 0);
}

TEST_CASE("a model's random_strengths go into its scene with every joint material they name",
          "[cut][model]") {
  nlohmann::json model = study_model();
  // "weak" is on no edge of the cut: without its random strength the cut would drop it.
  model["joint_materials"]["weak"] = {{"friction_angle", 25}, {"cohesion", 0}, {"tensile_strength", 0}};
  model["random_strengths"] = nlohmann::json::parse(R"({"variables": [
      {"joint_material": "default", "property": "friction_angle", "distribution": "normal",
       "mean": 35, "standard_deviation": 3, "min": 20, "max": 50},
      {"joint_material": "weak", "property": "friction_angle", "distribution": "normal",
       "mean": 25, "standard_deviation": 2, "min": 15, "max": 35}]})");
  const Model m = parse_model_text(model.dump(), "model.json");
  const CutScene out = cut_scene(m, cut_model(m.spec));
  REQUIRE(out.scene.contains("random_strengths"));
  CHECK(out.scene["joint_materials"].contains("weak"));
  const Scene scene = parse_scene_text(scene_text(out.scene), "cut.json");
  REQUIRE(scene.random_strengths.variables.size() == 2);
  CHECK(scene.random_strengths.variables[1].mean == 25.0);

  // A name the model does not define is the model's error at its place.
  model["random_strengths"]["variables"][1]["joint_material"] = "nowhere";
  const std::string why = model_error(model);
  CHECK(why.find("model.json: random_strengths.variables[1].joint_material") != std::string::npos);
}
