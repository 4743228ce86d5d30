// Scene input (io/scene_reader): a valid scene lands in the Scene struct field by field, and
// every kind of bad input is rejected with one message naming the file and the place in it,
// both by the reader and by the real command line (`dda run FILE` exits with code 2).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "support/cli_helpers.hpp"
#include "io/json_input.hpp"
#include "io/scene_reader.hpp"
#include "kinematics/polygon.hpp"
#include "solver/world.hpp"
#include "support/material_builders.hpp"

namespace fs = std::filesystem;

namespace {

// A valid scene that uses every key with a non-default value. Each bad scene below is this
// text with one edit, so that each test breaks exactly one rule. Block 1 is a triangle
// resting on block 0; the point load sits on their shared edge. The joint material
// "bonded" is listed before "default" (and sorts before it) to show that "default" still
// lands at index 0.
const std::string kValidScene = R"json({
  "description": "every key, non-default values",
  "gravity": [0.5, -9.0],
  "plane": "stress",
  "control": {"time_step": [0.01, 0.02], "steps": 40, "max_displacement_ratio": 0.005, "dynamic_coefficient": 0.5, "rotation_update": "original", "penalty": 2.5e10, "output_every": 5, "max_open_close": 5, "allowed_penetration": 2e-4},
  "materials": {
    "rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25},
    "clay": {"model": "elastic", "density": 1800, "young": 5e7, "poisson": 0.4}
  },
  "joint_materials": {
    "bonded": {"friction_angle": 35, "cohesion": 1e4, "tensile_strength": 5e3},
    "default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}
  },
  "blocks": [
    {"vertices": [[0, 0], [4, 0], [4, 1], [0, 1]], "material": "rock", "fixed": true},
    {"vertices": [[1, 1], [2, 1], [1.5, 2]], "material": "clay", "velocity": [0.1, -0.2, 0.3], "initial_stress": [-1e5, -2e5, 3e4]}
  ],
  "joints": [{"blocks": [1, 0], "material": "bonded"}],
  "pins": [{"point": [1.5, 1.5]}],
  "point_loads": [{"point": [1, 1], "force": [10, -20]}],
  "monitors": [{"name": "crest", "point": [1.5, 1.8]}, {"name": "toe", "point": [3, 0.5]}]
}
)json";


// A valid plane-strain scene with both plastic models, every plastic key given (not at its
// default). The bad plastic materials below are edits of it; kValidScene is plane stress,
// where plastic models are refused.
const std::string kPlasticScene = R"json({
  "plane": "strain",
  "control": {"time_step": 0.01, "steps": 1},
  "materials": {
    "soil": {"model": "mohr_coulomb", "density": 2000, "young": 5e7, "poisson": 0.3,
             "cohesion": 2e4, "friction_angle": 32, "dilation_angle": 8,
             "tensile_strength": 1e4, "hardening": [[0, 2e4], [0.01, 3e4], [0.05, 1e4]]},
    "clay": {"model": "drucker_prager", "density": 1800, "young": 2e7, "poisson": 0.35,
             "cohesion": 1e4, "friction_angle": 22, "dilation_angle": 22, "match": "inner",
             "hardening": [[0, 1e4], [0.02, 5e3]]},
    "rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}
  },
  "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
  "blocks": [
    {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "soil"},
    {"vertices": [[1, 0], [2, 0], [2, 1], [1, 1]], "material": "clay"},
    {"vertices": [[0, -1], [2, -1], [2, 0], [0, 0]], "material": "rock", "fixed": true}
  ]
}
)json";

// `text` with the one occurrence of `from` replaced by `to`. More than one occurrence, or
// none, is a mistake in the test itself.
std::string edit(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos || text.find(from, at + 1) != std::string::npos) {
    throw std::logic_error("test edit: \"" + from + "\" must occur exactly once");
  }
  return text.substr(0, at) + to + text.substr(at + from.size());
}

// A scene (kValidScene or an edit of it) with `extra`, the JSON text of one block, added at
// the end of its block list.
std::string with_block(const std::string& text, const std::string& extra) {
  const std::string last = "\"initial_stress\": [-1e5, -2e5, 3e4]}";
  return edit(text, last, last + ",\n    " + extra);
}

// `text` (a JSON document) with the value at `pointer` removed, or replaced by `value`.
// Used where the layout of the text does not matter to the message.
std::string without(const std::string& text, const std::string& pointer) {
  nlohmann::json document = nlohmann::json::parse(text);
  const nlohmann::json::json_pointer at(pointer);
  document[at.parent_pointer()].erase(at.back());
  return document.dump(2);
}

std::string with(const std::string& text, const std::string& pointer,
                 const nlohmann::json& value) {
  nlohmann::json document = nlohmann::json::parse(text);
  document[nlohmann::json::json_pointer(pointer)] = value;
  return document.dump(2);
}

using BadScene = dda::test::BadInput;

std::vector<BadScene> bad_scenes() {
  const std::string& s = kValidScene;
  const std::string& p = kPlasticScene;
  const std::string triangle = "[[1, 1], [2, 1], [1.5, 2]]";
  return {
      // ---- not JSON, or not the right kind of document ----
      // The comma after "stress" (line 4) is missing; nlohmann notices at the end of the next
      // token, the key "control" (line 5, columns 3 to 11), and reports that position.
      {"invalid JSON", edit(s, "stress\",", "stress\""), "line 5, column 11", {"invalid JSON"}},
      // JSON has no NaN; the position is the N.
      {"NaN literal (not JSON)", edit(s, "\"young\": 1e9", "\"young\": NaN"),
       "line 7, column 60", {"invalid JSON"}},
      {"duplicate key", edit(s, "\"plane\": \"stress\",", "\"plane\": \"stress\", \"plane\": \"strain\","),
       "plane", {"duplicate key"}},
      {"document is a list", "[1, 2]\n", "top level", {"expected an object", "list"}},
      {"empty file", "", "line 1, column 1", {"invalid JSON", "end of input"}},
      // ---- wrong types ----
      {"number expected", edit(s, "\"young\": 1e9", "\"young\": \"1e9\""), "materials.rock.young",
       {"expected a number", "a string (\"1e9\")"}},
      {"list expected", edit(s, "[0.5, -9.0]", "9.81"), "gravity", {"expected a list [gx, gy]"}},
      {"object expected", edit(s, "{\"point\": [1.5, 1.5]}", "[1.5, 1.5]"), "pins[0]",
       {"expected an object", "a list"}},
      {"string expected", edit(s, "\"material\": \"clay\"", "\"material\": 2"),
       "blocks[1].material", {"expected a string", "the number 2"}},
      {"bool expected", edit(s, "\"fixed\": true", "\"fixed\": \"yes\""), "blocks[0].fixed",
       {"expected true or false"}},
      {"integer expected", edit(s, "\"steps\": 40", "\"steps\": 40.5"), "control.steps",
       {"expected an integer", "40.5"}},
      {"list of 3 expected", edit(s, "[0.1, -0.2, 0.3]", "[0.1, -0.2]"), "blocks[1].velocity",
       {"expected a list of 3 numbers [vx, vy, omega]"}},
      {"vertex coordinate not a number", edit(s, "[4, 1]", "[4, \"1\"]"),
       "blocks[0].vertices[2][1]", {"expected a number"}},
      // ---- unknown keys (typos must not be ignored) ----
      {"unknown top-level key", edit(s, "\"plane\":", "\"plain\":"), "plain",
       {"unknown key", "did you mean \"plane\"", "known keys: description, gravity"}},
      {"unknown control key", edit(s, "\"time_step\":", "\"time_stepp\":"), "control.time_stepp",
       {"unknown key", "did you mean \"time_step\"", "output_every"}},
      {"unknown block key", edit(s, "\"fixed\": true", "\"fixed\": true, \"colour\": \"red\""),
       "blocks[0].colour", {"unknown key", "known keys: vertices, material"}},
      {"unknown material key", edit(s, "\"poisson\": 0.25}", "\"poisson\": 0.25, \"colour\": 1}"),
       "materials.rock.colour", {"unknown key", "known keys: model, density, young, poisson"}},
      {"plastic key in an elastic material",
       edit(s, "\"poisson\": 0.25}", "\"poisson\": 0.25, \"cohesion\": 1}"),
       "materials.rock.cohesion",
       {"not a key of the \"elastic\" model", "\"drucker_prager\" and \"mohr_coulomb\"",
        "keys of \"elastic\": model, density, young, poisson)"}},
      {"unknown pin key", edit(s, "{\"point\": [1.5, 1.5]}", "{\"point\": [1.5, 1.5], \"block\": 1}"),
       "pins[0].block", {"unknown key", "known keys: point"}},
      // ---- missing required fields ----
      {"missing control", without(s, "/control"), "control", {"required key is missing"}},
      {"missing materials", without(s, "/materials"), "materials", {"required key is missing"}},
      {"missing blocks", without(s, "/blocks"), "blocks", {"required key is missing"}},
      {"missing time_step", without(s, "/control/time_step"), "control.time_step",
       {"required key is missing"}},
      {"missing vertices", without(s, "/blocks/1/vertices"), "blocks[1].vertices",
       {"required key is missing"}},
      {"missing block material", without(s, "/blocks/1/material"), "blocks[1].material",
       {"required key is missing"}},
      {"missing model", without(s, "/materials/clay/model"), "materials.clay.model",
       {"required key is missing"}},
      {"missing density", without(s, "/materials/clay/density"), "materials.clay.density",
       {"required key is missing"}},
      {"missing young", without(s, "/materials/clay/young"), "materials.clay.young",
       {"required key is missing"}},
      {"missing poisson", without(s, "/materials/clay/poisson"), "materials.clay.poisson",
       {"required key is missing"}},
      {"missing pin point", without(s, "/pins/0/point"), "pins[0].point",
       {"required key is missing"}},
      {"missing force", without(s, "/point_loads/0/force"), "point_loads[0].force",
       {"required key is missing"}},
      {"empty block list", with(s, "/blocks", nlohmann::json::array()), "blocks",
       {"at least one block", "got 0"}},
      {"no materials", with(s, "/materials", nlohmann::json::object()), "materials",
       {"at least one material"}},
      // ---- polygons ----
      {"clockwise polygon", edit(s, triangle, "[[1, 1], [1.5, 2], [2, 1]]"), "blocks[1].vertices",
       {"clockwise", "counter-clockwise"}},
      {"self-crossing polygon", edit(s, triangle, "[[1, 1], [2, 2], [2, 1], [1, 2]]"),
       "blocks[1].vertices", {"crosses itself"}},
      {"fewer than 3 vertices", edit(s, triangle, "[[1, 1], [2, 1]]"), "blocks[1].vertices",
       {"at least 3 vertices", "got 2"}},
      {"zero area (collinear)", edit(s, triangle, "[[1, 1], [2, 1], [3, 1]]"),
       "blocks[1].vertices", {"zero area"}},
      {"first vertex repeated at the end", edit(s, triangle, "[[1, 1], [2, 1], [1.5, 2], [1, 1]]"),
       "blocks[1].vertices", {"repeats the first"}},
      // ---- numbers ----
      // nlohmann rejects literals that overflow a double; the reader reports them at their
      // place, with the line and the column where the literal starts.
      {"infinite number", edit(s, "\"young\": 1e9", "\"young\": 1e999"), "materials.rock.young",
       {"1e999", "too large", "line 7, column 60", "finite"}},
      {"infinite list element", edit(s, "[0.5, -9.0]", "[0.5, -1e999]"), "gravity[1]",
       {"too large", "line 3, column 20"}},
      {"density zero", edit(s, "\"density\": 2700", "\"density\": 0"), "materials.rock.density",
       {"must be positive, got 0"}},
      {"young negative", edit(s, "\"young\": 1e9", "\"young\": -1"), "materials.rock.young",
       {"must be positive, got -1"}},
      {"poisson 0.5", edit(s, "\"poisson\": 0.25", "\"poisson\": 0.5"), "materials.rock.poisson",
       {"greater than -1 and less than 0.5", "got 0.5"}},
      {"poisson -1", edit(s, "\"poisson\": 0.4", "\"poisson\": -1"), "materials.clay.poisson",
       {"greater than -1 and less than 0.5", "got -1"}},
      {"time step zero", edit(s, "[0.01, 0.02]", "[0.01, 0]"), "control.time_step[1]",
       {"must be positive"}},
      {"time step list empty", edit(s, "[0.01, 0.02]", "[]"), "control.time_step",
       {"must not be empty"}},
      {"steps zero", edit(s, "\"steps\": 40", "\"steps\": 0"), "control.steps",
       {"at least 1, got 0"}},
      {"end time negative", edit(s, "\"steps\": 40", "\"end_time\": -2"), "control.end_time",
       {"must be positive, got -2"}},
      {"displacement ratio above 1", edit(s, "0.005", "1.5"), "control.max_displacement_ratio",
       {"greater than 0 and at most 1", "got 1.5"}},
      {"dynamic coefficient below 0", edit(s, "\"dynamic_coefficient\": 0.5", "\"dynamic_coefficient\": -0.1"),
       "control.dynamic_coefficient", {"between 0 and 1"}},
      {"output_every zero", edit(s, "\"output_every\": 5", "\"output_every\": 0"),
       "control.output_every", {"at least 1"}},
      {"penalty negative", edit(s, "2.5e10", "-5"), "control.penalty", {"must be positive"}},
      {"penalty unknown word", edit(s, "2.5e10", "\"big\""), "control.penalty",
       {"positive number", "\"auto\""}},
      {"unknown energy_losses", edit(s, "\"output_every\": 5", "\"output_every\": 5, \"energy_losses\": \"warn\""),
       "control.energy_losses", {"unknown energy_losses \"warn\"", "\"report\", \"stop\""}},
      {"unknown vtk_format", edit(s, "\"output_every\": 5", "\"output_every\": 5, \"vtk_format\": \"xml\""),
       "control.vtk_format", {"unknown vtk_format \"xml\"", "\"binary\", \"ascii\""}},
      {"vtk_format not a string", edit(s, "\"output_every\": 5", "\"output_every\": 5, \"vtk_format\": 1"),
       "control.vtk_format", {"expected a string"}},
      // ---- run length ----
      {"both steps and end_time", edit(s, "\"steps\": 40", "\"steps\": 40, \"end_time\": 1"),
       "control", {"not both", "steps", "end_time"}},
      {"neither steps nor end_time", edit(s, "\"steps\": 40, ", ""), "control",
       {"steps", "end_time"}},
      // ---- names ----
      {"unknown material", edit(s, "\"material\": \"clay\"", "\"material\": \"granite\""),
       "blocks[1].material", {"unknown material \"granite\"", "\"clay\", \"rock\""}},
      {"unknown material model", edit(s, "\"model\": \"elastic\", \"density\": 1800",
                                      "\"model\": \"plastic\", \"density\": 1800"),
       "materials.clay.model",
       {"unknown model \"plastic\"", "\"elastic\", \"drucker_prager\" or \"mohr_coulomb\""}},
      {"unknown plane mode", edit(s, "\"plane\": \"stress\"", "\"plane\": \"3d\""), "plane",
       {"unknown plane mode \"3d\"", "\"strain\", \"stress\""}},
      {"unknown rotation update", edit(s, "\"original\"", "\"quaternion\""),
       "control.rotation_update", {"unknown rotation update \"quaternion\"", "\"original\"",
                                   "\"local_frame_as_printed\"", "\"finite_rotation\""}},
      // ---- pins and loads ----
      {"pin outside every block", edit(s, "{\"point\": [1.5, 1.5]}", "{\"point\": [10, 10]}"),
       "pins[0].point", {"(10, 10) is outside every block"}},
      {"point load outside every block", edit(s, "\"point\": [1, 1]", "\"point\": [-5, 3]"),
       "point_loads[0].point", {"(-5, 3) is outside every block"}},
      // ---- monitors ----
      {"monitor outside every block", edit(s, "\"point\": [3, 0.5]", "\"point\": [9, 9]"),
       "monitors[1].point", {"(9, 9) is outside every block"}},
      {"monitor without a name", edit(s, "\"name\": \"toe\", ", ""), "monitors[1].name",
       {"missing"}},
      {"monitor named twice", edit(s, "\"name\": \"toe\"", "\"name\": \"crest\""),
       "monitors[1].name", {"\"crest\" is already the name of another monitor"}},
      {"monitor name with a comma", edit(s, "\"name\": \"toe\"", "\"name\": \"to,e\""),
       "monitors[1].name", {"comma"}},
      {"monitor with an unknown key", edit(s, "\"name\": \"toe\"", "\"name\": \"toe\", \"block\": 0"),
       "monitors[1].block", {"unknown key (known keys: name, point)"}},
      // ---- control of contacts ----
      {"max_open_close 1", edit(s, "\"max_open_close\": 5", "\"max_open_close\": 1"),
       "control.max_open_close", {"at least 2, got 1"}},
      {"max_open_close not an integer", edit(s, "\"max_open_close\": 5", "\"max_open_close\": 2.5"),
       "control.max_open_close", {"expected an integer", "2.5"}},
      {"max_augmentations negative",
       edit(s, "\"max_open_close\": 5", "\"max_open_close\": 5, \"max_augmentations\": -1"),
       "control.max_augmentations", {"at least 0, got -1"}},
      {"max_augmentations above 50",
       edit(s, "\"max_open_close\": 5", "\"max_open_close\": 5, \"max_augmentations\": 51"),
       "control.max_augmentations", {"at most 50, got 51"}},
      {"allowed_penetration zero", edit(s, "2e-4", "0"), "control.allowed_penetration",
       {"must be positive, got 0"}},
      {"allowed_penetration unknown word", edit(s, "2e-4", "\"small\""),
       "control.allowed_penetration", {"positive number (m)", "\"auto\"", "\"small\""}},
      // ---- joint materials ----
      {"friction angle 90", edit(s, "\"friction_angle\": 35", "\"friction_angle\": 90"),
       "joint_materials.bonded.friction_angle",
       {"must be at least 0 and less than 90 (degrees)", "got 90"}},
      {"friction angle negative", edit(s, "\"friction_angle\": 30", "\"friction_angle\": -1"),
       "joint_materials.default.friction_angle",
       {"must be at least 0 and less than 90 (degrees)", "got -1"}},
      {"cohesion negative", edit(s, "\"cohesion\": 1e4", "\"cohesion\": -1"),
       "joint_materials.bonded.cohesion", {"must not be negative, got -1"}},
      {"tensile strength negative",
       edit(s, "\"tensile_strength\": 5e3", "\"tensile_strength\": -5"),
       "joint_materials.bonded.tensile_strength", {"must not be negative, got -5"}},
      {"missing friction angle", without(s, "/joint_materials/bonded/friction_angle"),
       "joint_materials.bonded.friction_angle", {"required key is missing"}},
      {"missing cohesion", without(s, "/joint_materials/default/cohesion"),
       "joint_materials.default.cohesion", {"required key is missing"}},
      {"missing tensile strength", without(s, "/joint_materials/bonded/tensile_strength"),
       "joint_materials.bonded.tensile_strength", {"required key is missing"}},
      {"unknown joint material key",
       edit(s, "\"cohesion\": 0,", "\"cohesion\": 0, \"dilation\": 5,"),
       "joint_materials.default.dilation",
       {"unknown key", "friction_angle, cohesion, tensile_strength"}},
      {"joint material not an object",
       edit(s, "\"bonded\": {\"friction_angle\": 35, \"cohesion\": 1e4, "
               "\"tensile_strength\": 5e3}",
            "\"bonded\": 35"),
       "joint_materials.bonded", {"expected an object", "the number 35"}},
      {"missing joint_materials with two blocks", without(s, "/joint_materials"), "joint_materials",
       {"required key is missing", "2 blocks", "\"default\" joint material"}},
      {"missing default joint material", without(s, "/joint_materials/default"),
       "joint_materials.default", {"required key is missing", "\"default\" joint material"}},
      // ---- joints ----
      {"unknown joint material in joints",
       edit(s, "\"material\": \"bonded\"", "\"material\": \"glued\""),
       "joints[0].material", {"unknown joint material \"glued\"", "\"default\", \"bonded\""}},
      {"joint block out of range", edit(s, "[1, 0]", "[1, 2]"), "joints[0].blocks[1]",
       {"block index 2 is out of range", "2 blocks", "from 0 to 1"}},
      {"joint block negative", edit(s, "[1, 0]", "[-1, 0]"), "joints[0].blocks[0]",
       {"block index -1 is out of range"}},
      {"joint block not an integer", edit(s, "[1, 0]", "[1, 0.5]"), "joints[0].blocks[1]",
       {"expected an integer", "0.5"}},
      {"joint between a block and itself", edit(s, "[1, 0]", "[1, 1]"), "joints[0].blocks",
       {"two different blocks", "block 1 twice"}},
      {"joint with three blocks", edit(s, "[1, 0]", "[1, 0, 1]"), "joints[0].blocks",
       {"expected a list of 2 block indices [i, j]", "3 element(s)"}},
      {"joint with one block", edit(s, "[1, 0]", "[1]"), "joints[0].blocks",
       {"give the two blocks as [i, j]", "got 1"}},
      {"joint pair listed twice", edit(s, "[{\"blocks\": [1, 0], \"material\": \"bonded\"}]",
                                       "[{\"blocks\": [1, 0], \"material\": \"bonded\"}, "
                                       "{\"blocks\": [0, 1], \"material\": \"default\"}]"),
       "joints[1].blocks", {"pair of blocks 0 and 1 is already given in joints[0].blocks"}},
      {"unknown joint key",
       edit(s, "\"material\": \"bonded\"", "\"material\": \"bonded\", \"friction_angle\": 5"),
       "joints[0].friction_angle", {"unknown key", "known keys: blocks, material"}},
      {"joints not a list", edit(s, "[{\"blocks\": [1, 0], \"material\": \"bonded\"}]", "{}"),
       "joints", {"expected a list", "an object"}},
      // ---- a block's edge joints ----
      {"edge joints of the wrong count",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}", "\"initial_stress\": [-1e5, -2e5, 3e4], \"edge_joints\": [\"bonded\", null]}"),
       "blocks[1].edge_joints", {"expected one entry per edge (3, as the block has vertices), got 2"}},
      {"unknown joint material on an edge",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}", "\"initial_stress\": [-1e5, -2e5, 3e4], \"edge_joints\": [\"bonded\", null, \"glued\"]}"),
       "blocks[1].edge_joints[2]", {"unknown joint material \"glued\"", "\"default\", \"bonded\""}},
      {"edge joints not a list",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}", "\"initial_stress\": [-1e5, -2e5, 3e4], \"edge_joints\": \"bonded\"}"),
       "blocks[1].edge_joints", {"expected a list"}},
      {"edge joint not a name",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}", "\"initial_stress\": [-1e5, -2e5, 3e4], \"edge_joints\": [1, null, null]}"),
       "blocks[1].edge_joints[0]", {"expected a string"}},
      {"edge bridges of the wrong count",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}", "\"initial_stress\": [-1e5, -2e5, 3e4], \"edge_bridges\": [null]}"),
       "blocks[1].edge_bridges", {"expected one entry per edge (3, as the block has vertices), got 1"}},
      {"edge bridge share above 1",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}", "\"initial_stress\": [-1e5, -2e5, 3e4], \"edge_bridges\": [null, {\"material\": \"bonded\", \"share\": 1.5}, null]}"),
       "blocks[1].edge_bridges[1].share", {"greater than 0 and at most 1", "1.5"}},
      {"edge bridge share zero",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}", "\"initial_stress\": [-1e5, -2e5, 3e4], \"edge_bridges\": [null, {\"material\": \"bonded\", \"share\": 0}, null]}"),
       "blocks[1].edge_bridges[1].share", {"greater than 0 and at most 1"}},
      {"edge bridge of an unknown material",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}", "\"initial_stress\": [-1e5, -2e5, 3e4], \"edge_bridges\": [null, {\"material\": \"rock\", \"share\": 0.5}, null]}"),
       "blocks[1].edge_bridges[1].material", {"unknown joint material \"rock\""}},
      {"edge bridge with an unknown key",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}", "\"initial_stress\": [-1e5, -2e5, 3e4], \"edge_bridges\": [null, {\"material\": \"bonded\", \"share\": 0.5, \"length\": 2}, null]}"),
       "blocks[1].edge_bridges[1].length", {"unknown key"}},
      // ---- plastic materials: the key set of each model ----
      {"misspelt plastic key", with(p, "/materials/soil/friction_angel", 30),
       "materials.soil.friction_angel", {"unknown key", "did you mean \"friction_angle\""}},
      {"tension cut-off in Drucker-Prager", with(p, "/materials/clay/tensile_strength", 0),
       "materials.clay.tensile_strength",
       {"not a key of the \"drucker_prager\" model", "it belongs to \"mohr_coulomb\""}},
      {"match in Mohr-Coulomb", with(p, "/materials/soil/match", "outer"), "materials.soil.match",
       {"not a key of the \"mohr_coulomb\" model", "it belongs to \"drucker_prager\""}},
      {"match in an elastic material", with(p, "/materials/rock/match", "outer"),
       "materials.rock.match", {"not a key of the \"elastic\" model"}},
      {"hardening in an elastic material", with(p, "/materials/rock/hardening", nlohmann::json::parse("[[0, 1]]")),
       "materials.rock.hardening", {"not a key of the \"elastic\" model"}},
      {"missing cohesion", without(p, "/materials/soil/cohesion"), "materials.soil.cohesion",
       {"required key is missing"}},
      {"missing friction angle (plastic)", without(p, "/materials/clay/friction_angle"),
       "materials.clay.friction_angle", {"required key is missing"}},
      {"plastic cohesion not a number", with(p, "/materials/soil/cohesion", "20 kPa"),
       "materials.soil.cohesion", {"expected a number", "a string (\"20 kPa\")"}},
      // ---- plastic materials: validate_material's rules, at the key they concern ----
      {"plastic friction angle 90", with(p, "/materials/soil/friction_angle", 90),
       "materials.soil.friction_angle", {"must be in [0, 90) degrees, got 90"}},
      {"plastic friction angle negative", with(p, "/materials/clay/friction_angle", -5),
       "materials.clay.friction_angle", {"must be in [0, 90) degrees, got -5"}},
      {"dilation above friction", with(p, "/materials/soil/dilation_angle", 40),
       "materials.soil.dilation_angle", {"must not exceed the friction angle (32 degrees)", "got 40"}},
      {"dilation negative", with(p, "/materials/clay/dilation_angle", -1),
       "materials.clay.dilation_angle", {"must be >= 0 degrees, got -1"}},
      {"plastic cohesion negative", with(p, "/materials/soil/cohesion", -1),
       "materials.soil.cohesion", {"must be >= 0 Pa, got -1"}},
      {"no cohesion and no friction",
       with(with(with(without(p, "/materials/clay/hardening"), "/materials/clay/cohesion", 0),
                 "/materials/clay/friction_angle", 0),
            "/materials/clay/dilation_angle", 0),
       "materials.clay.cohesion", {"needs cohesion > 0 or friction_angle > 0"}},
      {"tensile strength negative (plastic)", with(p, "/materials/soil/tensile_strength", -1),
       "materials.soil.tensile_strength", {"must be >= 0 Pa, got -1"}},
      {"unknown match", with(p, "/materials/clay/match", "middle"), "materials.clay.match",
       {"unknown match \"middle\"", "\"outer\", \"inner\" or \"plane_strain\""}},
      {"hardening eps_p not increasing",
       with(p, "/materials/soil/hardening", nlohmann::json::parse("[[0, 2e4], [0.01, 3e4], [0.01, 1e4]]")),
       "materials.soil.hardening[2]", {"eps_p must increase along the table", "got 0.01 after 0.01"}},
      {"hardening eps_p negative",
       with(p, "/materials/clay/hardening", nlohmann::json::parse("[[-0.01, 1e4], [0.02, 5e3]]")),
       "materials.clay.hardening[0]", {"eps_p must be >= 0, got -0.01"}},
      {"hardening cohesion negative",
       with(p, "/materials/clay/hardening", nlohmann::json::parse("[[0, 1e4], [0.02, -5]]")),
       "materials.clay.hardening[1]", {"cohesion must be >= 0 Pa, got -5"}},
      {"hardening not starting at the cohesion",
       with(p, "/materials/soil/hardening", nlohmann::json::parse("[[0, 1.5e4], [0.01, 3e4]]")),
       "materials.soil.cohesion", {"is 20000 Pa but the hardening table gives 15000 Pa at eps_p = 0"}},
      {"hardening row of 3 numbers",
       with(p, "/materials/soil/hardening", nlohmann::json::parse("[[0, 2e4, 1]]")),
       "materials.soil.hardening[0]", {"expected a list of 2 numbers [eps_p, cohesion]"}},
      {"hardening empty", with(p, "/materials/soil/hardening", nlohmann::json::array()),
       "materials.soil.hardening", {"at least one [eps_p, cohesion] row", "got 0"}},
      {"plastic model in plane stress", with(p, "/plane", "stress"), "materials.clay.model",
       {"need plane strain", "plane stress"}},
      // ---- rigid blocks ----
      {"rigid not a boolean (block)", edit(s, "\"fixed\": true", "\"fixed\": true, \"rigid\": 1"),
       "blocks[0].rigid", {"expected true or false", "the number 1"}},
      {"rigid not a boolean (material)",
       edit(s, "\"poisson\": 0.25}", "\"poisson\": 0.25, \"rigid\": \"yes\"}"),
       "materials.rock.rigid", {"expected true or false", "a string (\"yes\")"}},
      {"rigid plastic material", with(p, "/materials/soil/rigid", true), "materials.soil.rigid",
       {"a rigid material cannot be plastic (\"mohr_coulomb\")", "no strain to yield"}},
      {"rigid block of a plastic material", with(p, "/blocks/1/rigid", true), "blocks[1].rigid",
       {"a rigid block cannot be of a plastic material (\"clay\")", "elastic material"}},
      {"rigid block with an initial stress",
       edit(s, "\"initial_stress\": [-1e5, -2e5, 3e4]}",
            "\"initial_stress\": [-1e5, -2e5, 3e4], \"rigid\": true}"),
       "blocks[1].initial_stress",
       {"must be [0, 0, 0] or left out: the block is rigid", "carries no stress"}},
      {"block of a rigid material with an initial stress", with(s, "/materials/clay/rigid", true),
       "blocks[1].initial_stress",
       {"must be [0, 0, 0] or left out: its material \"clay\" is rigid"}},
      // ---- blocks overlapping at the start ----
      // The triangle pushed 0.5 m down into block 0: its base edge crosses block 0's sides.
      {"block overlaps another", edit(s, triangle, "[[1, 0.5], [2, 0.5], [1.5, 2]]"), "blocks[1]",
       {"overlaps blocks[0] at the start", "blocks may touch but not overlap"}},
      // A third block identical to block 1: no edges cross and no vertex is strictly inside
      // the other; the coincident edges give it away. Both places are named.
      {"block identical to another",
       with_block(s, "{\"vertices\": " + triangle + ", \"material\": \"rock\"}"), "blocks[2]",
       {"overlaps blocks[1] at the start"}},
  };
}

// Every message starts with the source name, then the place.
std::string reader_error(const std::string& text, const std::string& source) {
  try {
    (void)dda::parse_scene_text(text, source);
  } catch (const dda::InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

// ---- running the command line ----

using dda::test::CommandResult;
using dda::test::read_file;
using dda::test::run_command;
using dda::test::shell_quote;
using dda::test::write_file;

// A fresh directory for this test process's files, removed at the end.
struct TempDir : dda::test::TempDir {
  TempDir() : dda::test::TempDir("dda_scene_input_") {}
};

CommandResult run_dda(const fs::path& scene, const fs::path& out_dir) {
  return run_command(shell_quote(DDA_EXE) + " run " + shell_quote(scene.string()) + " --out " +
                     shell_quote(out_dir.string()));
}

std::string expected_prefix(const std::string& source, const std::string& place) {
  return source + ": " + place + ": ";
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Valid input

// Numbers are compared exactly: each is read from a decimal literal by the same conversion
// the test's literal goes through, so the doubles are identical.
TEST_CASE("a valid scene lands in the Scene struct field by field", "[scene][input]") {
  const dda::Scene scene = dda::parse_scene_text(kValidScene, "valid.json");
  CHECK(scene.source == "valid.json");
  CHECK(scene.gravity == dda::Vec2(0.5, -9.0));
  CHECK(scene.plane == dda::PlaneMode::Stress);

  const dda::ControlSettings& c = scene.control;
  CHECK(c.time_steps == std::vector<double>{0.01, 0.02});
  REQUIRE(c.steps.has_value());
  CHECK(*c.steps == 40);
  CHECK_FALSE(c.end_time.has_value());
  CHECK(c.max_displacement_ratio == 0.005);
  CHECK(c.dynamic_coefficient == 0.5);
  CHECK(c.rotation_update == dda::RotationUpdate::Original);
  REQUIRE(c.penalty.has_value());
  CHECK(*c.penalty == 2.5e10);
  CHECK(c.output_every == 5);
  CHECK(c.max_open_close == 5);
  REQUIRE(c.allowed_penetration.has_value());
  CHECK(*c.allowed_penetration == 2e-4);

  // "default" first, whatever the order in the file.
  REQUIRE(scene.joint_materials.size() == 2);
  const dda::JointMaterial& normal = scene.joint_materials[0];
  const dda::JointMaterial& bonded = scene.joint_materials[1];
  CHECK(normal.name == "default");
  CHECK(normal.friction_angle == 30.0);
  CHECK(normal.cohesion == 0.0);
  CHECK(normal.tensile_strength == 0.0);
  CHECK(bonded.name == "bonded");
  CHECK(bonded.friction_angle == 35.0);
  CHECK(bonded.cohesion == 1e4);
  CHECK(bonded.tensile_strength == 5e3);
  REQUIRE(scene.joints.size() == 1);
  CHECK(scene.joints[0].block_a == 1);
  CHECK(scene.joints[0].block_b == 0);
  CHECK(scene.joints[0].material == 1);
  CHECK(scene.warnings.empty());  // both joint materials are used

  REQUIRE(scene.materials.size() == 2);
  REQUIRE(scene.blocks.size() == 2);
  const dda::Material& rock = scene.materials[scene.blocks[0].material];
  const dda::Material& clay = scene.materials[scene.blocks[1].material];
  CHECK(rock.name == "rock");
  CHECK(rock.parameters.density == 2700.0);
  CHECK(rock.parameters.young == 1e9);
  CHECK(rock.parameters.poisson == 0.25);
  CHECK(clay.name == "clay");
  CHECK(clay.parameters.density == 1800.0);
  CHECK(clay.parameters.young == 5e7);
  CHECK(clay.parameters.poisson == 0.4);

  const dda::BlockSpec& base = scene.blocks[0];
  CHECK(base.vertices == dda::Polygon{{0, 0}, {4, 0}, {4, 1}, {0, 1}});
  CHECK(base.fixed);
  CHECK(base.velocity == dda::Vec3::Zero());
  CHECK(base.initial_stress == dda::Vec3::Zero());
  const dda::BlockSpec& top = scene.blocks[1];
  CHECK(top.vertices == dda::Polygon{{1, 1}, {2, 1}, {1.5, 2}});
  CHECK_FALSE(top.fixed);
  CHECK(top.velocity == dda::Vec3(0.1, -0.2, 0.3));
  CHECK(top.initial_stress == dda::Vec3(-1e5, -2e5, 3e4));

  REQUIRE(scene.pins.size() == 1);
  CHECK(scene.pins[0].point == dda::Vec2(1.5, 1.5));
  CHECK(scene.pins[0].block == 1);
  REQUIRE(scene.point_loads.size() == 1);
  CHECK(scene.point_loads[0].point == dda::Vec2(1, 1));
  CHECK(scene.point_loads[0].force == dda::Vec2(10, -20));
  // (1, 1) is on the edge both blocks share: the first block in the list takes it.
  CHECK(scene.point_loads[0].block == 0);
  REQUIRE(scene.monitors.size() == 2);
  CHECK(scene.monitors[0].name == "crest");
  CHECK(scene.monitors[0].point == dda::Vec2(1.5, 1.8));
  CHECK(scene.monitors[0].block == 1);
  CHECK(scene.monitors[1].name == "toe");
  CHECK(scene.monitors[1].block == 0);
}

TEST_CASE("plastic materials land in the Material struct, defaults where left out",
          "[scene][input]") {
  const dda::Scene scene = dda::parse_scene_text(kPlasticScene, "plastic.json");
  REQUIRE(scene.materials.size() == 3);
  // Materials are read in order of name: clay, rock, soil.
  const dda::Material& clay = scene.materials[0];
  const dda::Material& rock = scene.materials[1];
  const dda::Material& soil = scene.materials[2];
  CHECK(soil.name == "soil");
  CHECK(soil.parameters.model() == dda::MaterialModel::MohrCoulomb);
  CHECK(soil.parameters.density == 2000.0);
  CHECK(soil.parameters.young == 5e7);
  CHECK(soil.parameters.poisson == 0.3);
  CHECK(dda::test::strength_of(soil.parameters).cohesion == 2e4);
  CHECK(dda::test::strength_of(soil.parameters).friction_angle == 32.0);
  CHECK(dda::test::strength_of(soil.parameters).dilation_angle == 8.0);
  REQUIRE(dda::test::mohr_coulomb_of(soil.parameters).tensile_strength.has_value());
  CHECK(*dda::test::mohr_coulomb_of(soil.parameters).tensile_strength == 1e4);
  REQUIRE(dda::test::strength_of(soil.parameters).hardening.size() == 3);
  CHECK(dda::test::strength_of(soil.parameters).hardening[1].eps_p == 0.01);
  CHECK(dda::test::strength_of(soil.parameters).hardening[1].cohesion == 3e4);
  CHECK(dda::test::strength_of(soil.parameters).hardening[2].cohesion == 1e4);
  CHECK(clay.parameters.model() == dda::MaterialModel::DruckerPrager);
  CHECK(dda::test::drucker_prager_of(clay.parameters).match == dda::DruckerPragerMatch::Inner);
  CHECK(dda::test::strength_of(clay.parameters).dilation_angle == 22.0);
  CHECK(rock.parameters.model() == dda::MaterialModel::Elastic);
  // (Clay's tension cut-off and rock's hardening cannot be there: the Drucker-Prager and
  // elastic parameter structs have no such fields.)
  CHECK(scene.blocks[0].material == 2);

  // Left out: dilation_angle 0, match "plane_strain", no tension cut-off, no hardening.
  std::string minimal = without(kPlasticScene, "/materials/soil/dilation_angle");
  minimal = without(minimal, "/materials/soil/tensile_strength");
  minimal = without(minimal, "/materials/soil/hardening");
  minimal = without(minimal, "/materials/clay/match");
  const dda::Scene defaults = dda::parse_scene_text(minimal, "minimal.json");
  CHECK(dda::test::strength_of(defaults.materials[2].parameters).dilation_angle == 0.0);
  CHECK_FALSE(
      dda::test::mohr_coulomb_of(defaults.materials[2].parameters).tensile_strength.has_value());
  CHECK(dda::test::strength_of(defaults.materials[2].parameters).hardening.empty());
  CHECK(dda::test::drucker_prager_of(defaults.materials[0].parameters).match ==
        dda::DruckerPragerMatch::PlaneStrain);
  // Every match is read by its name; a tension cut-off of 0 (no tension) is allowed.
  for (const auto& [name, value] : {std::pair{"outer", dda::DruckerPragerMatch::Outer},
                                    std::pair{"inner", dda::DruckerPragerMatch::Inner},
                                    std::pair{"plane_strain", dda::DruckerPragerMatch::PlaneStrain}}) {
    INFO(name);
    CHECK(dda::test::drucker_prager_of(
              dda::parse_scene_text(with(kPlasticScene, "/materials/clay/match", name), "m.json")
                  .materials[0]
                  .parameters)
              .match == value);
  }
  CHECK(*dda::test::mohr_coulomb_of(
             dda::parse_scene_text(with(kPlasticScene, "/materials/soil/tensile_strength", 0), "t.json")
                 .materials[2]
                 .parameters)
             .tensile_strength == 0.0);
}

TEST_CASE("rigid: a block's key overrides its material's, and the world follows",
          "[scene][input][rigid]") {
  // Material "rock" rigid, "clay" not; block 0 takes rock's, block 1 says rigid on clay,
  // block 2 says not rigid on rock. A zero initial stress on a rigid block is accepted.
  const std::string text = R"json({
  "control": {"time_step": 0.01, "steps": 1},
  "materials": {
    "rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25, "rigid": true},
    "clay": {"model": "elastic", "density": 1800, "young": 5e7, "poisson": 0.4}
  },
  "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
  "blocks": [
    {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock", "initial_stress": [0, 0, 0]},
    {"vertices": [[1, 0], [2, 0], [2, 1], [1, 1]], "material": "clay", "rigid": true},
    {"vertices": [[2, 0], [3, 0], [3, 1], [2, 1]], "material": "rock", "rigid": false}
  ]
}
)json";
  const dda::Scene scene = dda::parse_scene_text(text, "rigid.json");
  REQUIRE(scene.materials.size() == 2);
  CHECK(scene.materials[0].name == "clay");
  CHECK_FALSE(scene.materials[0].rigid);
  CHECK(scene.materials[1].rigid);
  CHECK_FALSE(scene.blocks[0].rigid.has_value());
  CHECK(scene.blocks[1].rigid == std::optional<bool>(true));
  CHECK(scene.blocks[2].rigid == std::optional<bool>(false));
  const dda::World world = dda::make_world(scene);
  CHECK(world.blocks[0].rigid);
  CHECK(world.blocks[1].rigid);
  CHECK_FALSE(world.blocks[2].rigid);
  // Six slots of d per free block, rigid or not (the solvers see fewer).
  CHECK(world.dof_count == 18);
  CHECK(dda::elastic_of(world, world.blocks[1]) == dda::Mat3::Zero());
  // Left out, "rigid" is false.
  CHECK_FALSE(dda::parse_scene_text(kValidScene, "valid.json").materials[0].rigid);
}

TEST_CASE("every rotation update is read by its name", "[scene][input]") {
  const std::pair<const char*, dda::RotationUpdate> names[] = {
      {"original", dda::RotationUpdate::Original},
      {"second_order", dda::RotationUpdate::SecondOrder},
      {"post_adjustment", dda::RotationUpdate::PostAdjustment},
      {"local_frame", dda::RotationUpdate::LocalFrame},
      {"local_frame_as_printed", dda::RotationUpdate::LocalFrameAsPrinted},
      {"sin_variable", dda::RotationUpdate::SinVariable},
      {"finite_rotation", dda::RotationUpdate::FiniteRotation}};
  for (const auto& [name, value] : names) {
    INFO(name);
    std::string quoted = "\"";
    quoted += name;
    quoted += '"';
    const std::string text = edit(kValidScene, "\"original\"", quoted);
    CHECK(dda::parse_scene_text(text, "valid.json").control.rotation_update == value);
  }
}

TEST_CASE("optional keys take their documented defaults", "[scene][input]") {
  const std::string minimal = R"json({
    "control": {"time_step": 0.01, "end_time": 2.5},
    "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
    "blocks": [{"vertices": [[0, 0], [1, 0], [0, 1]], "material": "rock"}]
  })json";
  const dda::Scene scene = dda::parse_scene_text(minimal, "minimal.json");
  CHECK(scene.gravity == dda::Vec2(0.0, -9.81));
  CHECK(scene.plane == dda::PlaneMode::Strain);
  CHECK(scene.control.time_steps == std::vector<double>{0.01});
  CHECK_FALSE(scene.control.steps.has_value());
  REQUIRE(scene.control.end_time.has_value());
  CHECK(*scene.control.end_time == 2.5);
  CHECK(scene.control.max_displacement_ratio == 0.01);
  CHECK(scene.control.dynamic_coefficient == 1.0);
  CHECK(scene.control.rotation_update == dda::RotationUpdate::FiniteRotationPolar);
  CHECK_FALSE(scene.control.penalty.has_value());  // "auto"
  CHECK(scene.control.output_every == 10);
  CHECK(scene.control.vtk_binary);  // "binary", ParaView's own encoding
  CHECK(scene.control.max_open_close == 8);
  CHECK(scene.control.max_augmentations == 5);
  CHECK_FALSE(scene.control.allowed_penetration.has_value());  // "auto"
  // One block needs no joint materials: the built-in frictionless, unbonded default stays.
  REQUIRE(scene.joint_materials.size() == 1);
  CHECK(scene.joint_materials[0].name == "default");
  CHECK(scene.joint_materials[0].friction_angle == 0.0);
  CHECK(scene.joint_materials[0].cohesion == 0.0);
  CHECK(scene.joint_materials[0].tensile_strength == 0.0);
  CHECK(scene.joints.empty());
  CHECK(scene.warnings.empty());
  CHECK_FALSE(scene.blocks[0].fixed);
  CHECK(scene.blocks[0].velocity == dda::Vec3::Zero());
  CHECK(scene.blocks[0].initial_stress == dda::Vec3::Zero());
  CHECK(scene.pins.empty());
  CHECK(scene.point_loads.empty());
}

TEST_CASE("penalty auto and whole numbers written as floats are accepted", "[scene][input]") {
  std::string text = edit(kValidScene, "2.5e10", "\"auto\"");
  text = edit(text, "\"steps\": 40", "\"steps\": 4e1");
  text = edit(text, "2e-4", "\"auto\"");
  text = edit(text, "[1, 0]", "[1.0, 0e3]");
  const dda::Scene scene = dda::parse_scene_text(text, "auto.json");
  CHECK_FALSE(scene.control.penalty.has_value());
  CHECK_FALSE(scene.control.allowed_penetration.has_value());
  CHECK(scene.control.steps == 40);
  REQUIRE(scene.joints.size() == 1);
  CHECK(scene.joints[0].block_a == 1);
  CHECK(scene.joints[0].block_b == 0);
}

TEST_CASE("joint_materials: the edges of the ranges are accepted", "[scene][input]") {
  // Friction angle 0 (frictionless) and just under 90 degrees, cohesion and tensile
  // strength 0, are all inside the documented ranges.
  std::string text = edit(kValidScene, "\"friction_angle\": 35", "\"friction_angle\": 89.999");
  text = edit(text, "\"friction_angle\": 30", "\"friction_angle\": 0");
  const dda::Scene scene = dda::parse_scene_text(text, "edges.json");
  CHECK(scene.joint_materials[0].friction_angle == 0.0);
  CHECK(scene.joint_materials[1].friction_angle == 89.999);
  // No "joints": every pair uses "default", and "bonded" is left unused (a warning only).
  const dda::Scene no_joints = dda::parse_scene_text(without(kValidScene, "/joints"), "nj.json");
  CHECK(no_joints.joints.empty());
  REQUIRE(no_joints.warnings.size() == 1);
  CHECK(no_joints.warnings[0] ==
        "nj.json: joint_materials.bonded: not used by any pair of blocks (name it in \"joints\")");
}

TEST_CASE("a joint material no pair of blocks uses is a warning, not an error",
          "[scene][input]") {
  const std::string text = edit(
      kValidScene, "\"default\": {",
      "\"weak\": {\"friction_angle\": 10, \"cohesion\": 0, \"tensile_strength\": 0},\n    "
      "\"default\": {");
  const dda::Scene scene = dda::parse_scene_text(text, "warn.json");
  REQUIRE(scene.joint_materials.size() == 3);
  CHECK(scene.joint_materials[0].name == "default");
  REQUIRE(scene.warnings.size() == 1);
  CHECK(scene.warnings[0] ==
        "warn.json: joint_materials.weak: not used by any pair of blocks (name it in \"joints\")");

  // With one block, joint materials are optional; without "default" the built-in one stays
  // at index 0, and the others (used by no pair, as there is none) are warned about.
  const std::string one_block = R"json({
    "control": {"time_step": 0.01, "steps": 1},
    "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
    "joint_materials": {"weak": {"friction_angle": 10, "cohesion": 0, "tensile_strength": 0}},
    "blocks": [{"vertices": [[0, 0], [1, 0], [0, 1]], "material": "rock"}]
  })json";
  const dda::Scene single = dda::parse_scene_text(one_block, "one.json");
  REQUIRE(single.joint_materials.size() == 2);
  CHECK(single.joint_materials[0].name == "default");
  CHECK(single.joint_materials[0].friction_angle == 0.0);
  CHECK(single.joint_materials[1].name == "weak");
  REQUIRE(single.warnings.size() == 1);
  CHECK(single.warnings[0].find("one.json: joint_materials.weak: not used") == 0);
}

TEST_CASE("a frictional plastic material without dilation or a tension cut-off is warned about",
          "[scene][input][materials]") {
  // Mohr-Coulomb with psi = 0 and no cut-off has no return beyond its apex (c cot phi in
  // mean tension): a free block of it that an impact puts in tension stops the run
  // (tests/solver/test_material_coupling.cpp). The warning names the material and the apex:
  // c = 1 kPa, phi = 30 degrees: 1000 / tan 30 = 1732.05 Pa.
  auto scene_with = [](const std::string& soil, bool fixed) {
    return std::string(R"json({
    "control": {"time_step": 0.01, "steps": 1},
    "materials": {"soil": )json") + soil + R"json(},
    "blocks": [{"vertices": [[0, 0], [1, 0], [0, 1]], "material": "soil", "fixed": )json" +
           (fixed ? "true" : "false") + "}]\n  }";
  };
  const std::string mc = R"({"model": "mohr_coulomb", "density": 2000, "young": 1e7, "poisson": 0.3, "cohesion": 1000, "friction_angle": 30)";
  const dda::Scene plain = dda::parse_scene_text(scene_with(mc + "}", false), "apex.json");
  REQUIRE(plain.warnings.size() == 1);
  CHECK(plain.warnings[0].find("apex.json: materials.soil: mohr_coulomb with dilation_angle 0 and "
                               "no tensile_strength has no return for a stress beyond its apex") == 0);
  CHECK(plain.warnings[0].find("1732.05 Pa") != std::string::npos);
  // A cut-off or a dilation angle gives such stresses a return; a fixed block never strains.
  CHECK(dda::parse_scene_text(scene_with(mc + R"(, "tensile_strength": 0})", false), "a.json").warnings.empty());
  CHECK(dda::parse_scene_text(scene_with(mc + R"(, "dilation_angle": 5})", false), "a.json").warnings.empty());
  CHECK(dda::parse_scene_text(scene_with(mc + "}", true), "a.json").warnings.size() == 1);  // every block fixed
  CHECK(dda::parse_scene_text(scene_with(mc + "}", true), "a.json").warnings[0].find("every block is fixed") !=
        std::string::npos);
  // Drucker-Prager likewise, without the cut-off (it has none).
  const std::string dp = R"({"model": "drucker_prager", "density": 2000, "young": 1e7, "poisson": 0.3, "cohesion": 1000, "friction_angle": 30})";
  const dda::Scene cone = dda::parse_scene_text(scene_with(dp, false), "dp.json");
  REQUIRE(cone.warnings.size() == 1);
  CHECK(cone.warnings[0].find("dp.json: materials.soil: drucker_prager with dilation_angle 0 has no "
                              "return") == 0);
}

TEST_CASE("blocks that touch are accepted, wherever they touch", "[scene][input]") {
  // A third block on block 0 whose left corner is block 1's right corner (2, 1): it shares
  // a vertex with block 1 and part of an edge with block 0; block 1 also stands on block 0.
  const dda::Scene scene = dda::parse_scene_text(
      with_block(kValidScene, R"({"vertices": [[2, 1], [3, 1], [2.5, 2]], "material": "clay"})"),
      "touch.json");
  CHECK(scene.blocks.size() == 3);
  // A square whose bottom-left corner lies on block 1's right side (the segment from (2, 1)
  // to (1.5, 2)) at its midpoint (1.75, 1.5): a vertex on a sloping edge.
  CHECK_NOTHROW(dda::parse_scene_text(
      with_block(kValidScene, R"({"vertices": [[1.75, 1.5], [2.75, 1.5], [2.75, 2.5],
                                               [1.75, 2.5]], "material": "clay"})"),
      "vertex_on_edge.json"));
}

// A 100 x 100 grid of unit squares sharing edges and corners: every neighbour touches,
// none overlaps. With an all-pairs test this would be 5e7 polygon pairs; the broad phase
// leaves only the ~4e4 pairs of neighbours. Then one extra square, half a square off the
// grid, overlaps four of them: the message names it and the first one it overlaps.
TEST_CASE("the overlap check scales to 10000 touching blocks", "[scene][input]") {
  constexpr int kSide = 100;
  std::string blocks;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      const std::string x0 = std::to_string(i), x1 = std::to_string(i + 1);
      const std::string y0 = std::to_string(j), y1 = std::to_string(j + 1);
      blocks += std::string(blocks.empty() ? "" : ",\n") + "{\"vertices\": [[" + x0 + ", " + y0 +
                "], [" + x1 + ", " + y0 + "], [" + x1 + ", " + y1 + "], [" + x0 + ", " + y1 +
                "]], \"material\": \"rock\"}";
    }
  }
  const auto scene_with = [](const std::string& block_list) {
    return R"json({
      "control": {"time_step": 0.01, "steps": 1},
      "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
      "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
      "blocks": [)json" + block_list + "]}";
  };
  const dda::Scene grid = dda::parse_scene_text(scene_with(blocks), "grid.json");
  CHECK(grid.blocks.size() == kSide * kSide);
  // Block index of square (i, j) is i * kSide + j; the extra square [50.5, 51.5] x
  // [50.5, 51.5] overlaps squares (50, 50), (50, 51), (51, 50), (51, 51), first 5050.
  const std::string extra = R"({"vertices": [[50.5, 50.5], [51.5, 50.5], [51.5, 51.5],
                                              [50.5, 51.5]], "material": "rock"})";
  CHECK(reader_error(scene_with(blocks + ",\n" + extra), "grid.json") ==
        "grid.json: blocks[10000]: overlaps blocks[5050] at the start (blocks may touch but not "
        "overlap)");
}

TEST_CASE("read_scene_file names the scene by its path", "[scene][input]") {
  TempDir dir;
  const fs::path file = dir.path / "scene.json";
  write_file(file, kValidScene);
  CHECK(dda::read_scene_file(file.string()).source == file.string());
}

// ---------------------------------------------------------------------------------------
// Bad input, through the reader

TEST_CASE("every bad scene is rejected by the reader with its place and reason",
          "[scene][input]") {
  for (const BadScene& bad : bad_scenes()) {
    INFO("case: " << bad.name);
    const std::string message = reader_error(bad.text, "bad.json");
    INFO("message: " << message);
    CHECK(message.rfind(expected_prefix("bad.json", bad.place), 0) == 0);
    for (const std::string& word : bad.words) CHECK(message.find(word) != std::string::npos);
  }
}

TEST_CASE("distinct bad scenes give distinct messages", "[scene][input]") {
  std::vector<std::string> messages;
  for (const BadScene& bad : bad_scenes()) messages.push_back(reader_error(bad.text, "bad.json"));
  std::sort(messages.begin(), messages.end());
  const auto repeated = std::adjacent_find(messages.begin(), messages.end());
  INFO("repeated message: " << (repeated == messages.end() ? "" : *repeated));
  CHECK(repeated == messages.end());
}

TEST_CASE("a sliver far thinner than the block's size counts as zero area", "[scene][input]") {
  // Height 1e-13 over a base of 1: |area| = 5e-14 <= 1e-12 x diagonal^2 (about 1.25), the
  // reader's zero-area tolerance; a height of 1e-6 is a (thin) real block.
  const std::string triangle = "[[1, 1], [2, 1], [1.5, 2]]";
  const std::string sliver = edit(kValidScene, triangle, "[[1, 1], [2, 1], [1.5, 1.0000000000001]]");
  CHECK_THAT(reader_error(sliver, "bad.json"),
             Catch::StartsWith("bad.json: blocks[1].vertices: ") && Catch::Contains("zero area"));
  const std::string thin = edit(kValidScene, triangle, "[[1, 1], [2, 1], [1.5, 1.000001]]");
  // (The pin and the crest monitor moved onto the thin block's base.)
  const std::string points_on_base =
      edit(edit(thin, "{\"point\": [1.5, 1.5]}", "{\"point\": [1.5, 1]}"), "[1.5, 1.8]", "[1.5, 1]");
  CHECK_NOTHROW(dda::parse_scene_text(points_on_base, "thin.json"));
}

TEST_CASE("an unreadable scene file is an input error naming the path", "[scene][input]") {
  TempDir dir;
  const std::string missing = (dir.path / "no_such_scene.json").string();
  CHECK_THROWS_WITH(dda::read_scene_file(missing),
                    Catch::StartsWith(missing + ": cannot open file") &&
                        Catch::Contains("No such file"));
  CHECK_THROWS_WITH(dda::read_scene_file(dir.path.string()),
                    Catch::StartsWith(dir.path.string() + ": cannot open") &&
                        Catch::Contains("directory"));
}

TEST_CASE("JSON error positions are lines and columns as an editor shows them",
          "[scene][input]") {
  // Byte positions are 1-based (nlohmann's convention): byte 1 is the first character.
  const std::string text = "ab\ncd\n\xC3\xA9x";  // line 3 starts with a two-byte character
  CHECK(dda::input::position_of_byte(text, 1).line == 1);
  CHECK(dda::input::position_of_byte(text, 1).column == 1);
  CHECK(dda::input::position_of_byte(text, 5).line == 2);
  CHECK(dda::input::position_of_byte(text, 5).column == 2);
  CHECK(dda::input::position_of_byte(text, 9).line == 3);
  CHECK(dda::input::position_of_byte(text, 9).column == 2);  // the 'x' after the e-acute
}

// ---------------------------------------------------------------------------------------
// Bad input, through the command line: exit code 2 and the message on stderr

TEST_CASE("dda run exits with code 2 and names the place for every bad scene", "[scene][cli]") {
  TempDir dir;
  int index = 0;
  for (const BadScene& bad : bad_scenes()) {
    const fs::path file = dir.path / ("bad_" + std::to_string(index++) + ".json");
    write_file(file, bad.text);
    const CommandResult result = run_dda(file, dir.path / "out");
    INFO("case: " << bad.name);
    INFO("output: " << result.output);
    CHECK(result.exit_code == 2);
    const std::string prefix = "dda: error: " + expected_prefix(file.string(), bad.place);
    CHECK(result.output.find(prefix) != std::string::npos);
    for (const std::string& word : bad.words) CHECK(result.output.find(word) != std::string::npos);
  }
}

TEST_CASE("dda run exits with code 2 when the scene file cannot be opened", "[scene][cli]") {
  TempDir dir;
  const fs::path missing = dir.path / "no_such_scene.json";
  const CommandResult result = run_dda(missing, dir.path / "out");
  INFO("output: " << result.output);
  CHECK(result.exit_code == 2);
  CHECK(result.output.find("dda: error: " + missing.string() + ": cannot open file") !=
        std::string::npos);

  const CommandResult on_dir = run_dda(dir.path, dir.path / "out");
  INFO("output: " << on_dir.output);
  CHECK(on_dir.exit_code == 2);
  CHECK(on_dir.output.find("is a directory") != std::string::npos);
}

TEST_CASE("dda run prints a warning for an unused joint material and runs", "[scene][cli]") {
  // Two blocks far apart (they never meet in 2 steps), so the run is short and contact-free.
  const std::string text = R"json({
    "control": {"time_step": 0.01, "steps": 2},
    "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
    "joint_materials": {
      "default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0},
      "weak": {"friction_angle": 10, "cohesion": 0, "tensile_strength": 0}
    },
    "blocks": [
      {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock"},
      {"vertices": [[5, 0], [6, 0], [6, 1], [5, 1]], "material": "rock"}
    ]
  })json";
  TempDir dir;
  const fs::path file = dir.path / "warn.json";
  write_file(file, text);
  const CommandResult result = run_dda(file, dir.path / "out");
  INFO("output: " << result.output);
  CHECK(result.exit_code == 0);
  CHECK(result.output.find("dda: warning: " + file.string() +
                           ": joint_materials.weak: not used by any pair of blocks (name it in "
                           "\"joints\")") != std::string::npos);
  CHECK(fs::exists(dir.path / "out" / "summary.json"));
}

// ---------------------------------------------------------------------------------------
// The shipped scenes

TEST_CASE("the built-in default scene parses and is scenes/default.json", "[scene][input]") {
  const dda::Scene scene = dda::parse_scene_text(dda::default_scene_text(), dda::kDefaultSceneName);
  CHECK(scene.source == dda::kDefaultSceneName);
  REQUIRE(scene.blocks.size() == 3);
  CHECK(scene.blocks[2].fixed);  // the floor
  REQUIRE(scene.pins.size() == 1);
  CHECK(scene.pins[0].block == 0);  // the pendulum
  CHECK(scene.blocks[1].velocity == dda::Vec3(1, 3, 2));
  CHECK(scene.control.time_steps == std::vector<double>{0.005});
  CHECK(scene.control.end_time == 3.0);
  REQUIRE(scene.joint_materials.size() == 1);
  CHECK(scene.joint_materials[0].friction_angle == 30.0);
  CHECK(scene.warnings.empty());

  // The two free blocks do not overlap: their bounding boxes are apart.
  const dda::Box pendulum = dda::bounding_box(scene.blocks[0].vertices);
  const dda::Box octagon = dda::bounding_box(scene.blocks[1].vertices);
  CHECK(octagon.max.x() < pendulum.min.x());

  // Same content as the shipped file (compared as JSON, so layout does not matter).
  const std::string file = read_file(fs::path(DDA_SOURCE_DIR) / "scenes" / "default.json");
  CHECK(nlohmann::json::parse(file) == nlohmann::json::parse(dda::default_scene_text()));
}

TEST_CASE("every scene in scenes/ parses", "[scene][input]") {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(DDA_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    INFO("scene: " << entry.path());
    CHECK_NOTHROW(dda::read_scene_file(entry.path().string()));
    ++count;
  }
  CHECK(count >= 4);
}


// ---------------------------------------------------------------------------------------
// A run that diverges

TEST_CASE("a diverging run stops with a message, exit code 3, and keeps what it wrote",
          "[scene][input]") {
  // A block resting on a fixed base under gravity compresses its contacts by m g / 2p
  // (~1e-6 m with the auto penalty); without the augmented-Lagrangian rounds
  // (max_augmentations 0) an allowed penetration of 1e-12 m cannot be met: the step is cut
  // six times, the penalty is left as it is, and the run gives up at step 1.
  TempDir dir;
  const fs::path scene = dir.path / "diverge.json";
  write_file(scene, R"({
    "control": {"time_step": 0.01, "steps": 5, "allowed_penetration": 1e-12,
                "max_augmentations": 0},
    "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
    "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
    "blocks": [
      {"vertices": [[-1.5, -1], [1.5, -1], [1.5, 0], [-1.5, 0]], "material": "rock", "fixed": true},
      {"vertices": [[-0.5, 0], [0.5, 0], [0.5, 1], [-0.5, 1]], "material": "rock"}
    ]
  })");
  const fs::path out = dir.path / "out";
  const CommandResult r =
      run_command(std::string(DDA_EXE) + " run " + shell_quote(scene.string()) + " --out " +
                  shell_quote(out.string()));
  INFO(r.output);
  CHECK(r.exit_code == 3);
  CHECK(r.output.find("dda: error: the run diverged at step 1") != std::string::npos);
  CHECK(r.output.find("allowed_penetration") != std::string::npos);
  // What was written is kept: the initial state in the history and a summary saying why.
  const nlohmann::json summary = nlohmann::json::parse(read_file(out / "summary.json"));
  CHECK(summary["diverged"] == true);
  CHECK(summary["penalty_raises"] == 0);  // the penalty is never changed
  CHECK(summary["message"].get<std::string>().find("allowed_penetration") != std::string::npos);
  CHECK(summary["steps"] == 0);
  const std::string history = read_file(out / "history.csv");
  CHECK(std::count(history.begin(), history.end(), '\n') == 1 + 2);  // header + step 0 rows
  CHECK(fs::exists(out / "blocks.pvd"));
}

TEST_CASE("control.inertia is read by its name and refused where it cannot apply",
          "[scene][input]") {
  // kValidScene uses "original", which has no block frame: "pseudo_rigid" is refused there
  // with the reason, "shi" and "auto" are accepted; with finite_rotation all three are.
  const auto with = [](const std::string& update, const std::string& inertia) {
    return edit(kValidScene, "\"rotation_update\": \"original\"",
                "\"rotation_update\": \"" + update + "\", \"inertia\": \"" + inertia + "\"");
  };
  CHECK(dda::parse_scene_text(with("original", "shi"), "v.json").control.inertia ==
        dda::Inertia::Shi);
  CHECK_FALSE(dda::parse_scene_text(with("original", "auto"), "v.json").control.inertia);
  CHECK(dda::parse_scene_text(with("finite_rotation", "pseudo_rigid"), "v.json").control.inertia ==
        dda::Inertia::PseudoRigid);
  try {
    dda::parse_scene_text(with("original", "pseudo_rigid"), "v.json");
    FAIL("pseudo_rigid with original was accepted");
  } catch (const dda::InputError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("control.inertia") != std::string::npos);
    CHECK(what.find("block frame") != std::string::npos);
  }
  try {
    dda::parse_scene_text(with("finite_rotation", "newton"), "v.json");
    FAIL("an unknown inertia was accepted");
  } catch (const dda::InputError& e) {
    CHECK(std::string(e.what()).find("unknown inertia \"newton\"") != std::string::npos);
  }
}
