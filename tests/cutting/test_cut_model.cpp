// `dda cut` (docs/cutting.md): a cutting model read with located errors (io/model_reader), cut and
// labelled (cutting/cut_model: region materials, fixed blocks, the joint material of each
// pair of neighbours from the joints that made their shared edge), written as a scene that
// the scene reader takes without a warning and that runs; the command line's exit codes;
// the example slope's block count.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"
#include "cutting/model.hpp"
#include "io/cut_scene.hpp"
#include "io/model_reader.hpp"
#include "io/scene_reader.hpp"
#include "kinematics/overlap.hpp"
#include "kinematics/polygon.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"

using namespace dda;
namespace fs = std::filesystem;
using dda::test::edit;
using dda::test::run_command;
using dda::test::shell_quote;

namespace {

// Pieces of the test model that the tests edit.
const std::string kSet =
    "{\"dip\": 0, \"spacing\": 2.5, \"offset\": 1.25, \"joint_material\": \"bedding\"}";
const std::string kFaultJoints =
    "\"joints\": [{\"from\": [5, -1], \"to\": [5, 11], \"joint_material\": \"fault\"}]";
const std::string kRegionPolygon = "[[-1, -1], [5, -1], [5, 11], [-1, 11]]";

// A 10 m x 10 m square cut by a horizontal set (y = 1.25, 3.75, 6.25, 8.75; "bedding") and a
// vertical single joint at x = 5 ("fault"): 5 rows x 2 columns of blocks. The left half is a
// region of "weak" rock, the blocks on the bottom edge (edge 0) and those inside the top
// strip y >= 8 are fixed.
const std::string kModel = R"({
  "description": "test model",
  "gravity": [0, -9.81],
  "control": {"time_step": 0.001, "steps": 5},
  "materials": {
    "rock": {"model": "elastic", "density": 2600, "young": 1e9, "poisson": 0.25},
    "weak": {"model": "elastic", "density": 2200, "young": 1e8, "poisson": 0.3}
  },
  "joint_materials": {
    "default": {"friction_angle": 35, "cohesion": 0, "tensile_strength": 0},
    "bedding": {"friction_angle": 20, "cohesion": 0, "tensile_strength": 0},
    "fault": {"friction_angle": 15, "cohesion": 0, "tensile_strength": 0},
    "spare": {"friction_angle": 10, "cohesion": 0, "tensile_strength": 0}
  },
  "material": "rock",
  "domain": [[0, 0], [10, 0], [10, 10], [0, 10]],
  "joint_sets": [
    {"dip": 0, "spacing": 2.5, "offset": 1.25, "joint_material": "bedding"}
  ],
  "seed": 7,
  "joints": [{"from": [5, -1], "to": [5, 11], "joint_material": "fault"}],
  "regions": [{"polygon": [[-1, -1], [5, -1], [5, 11], [-1, 11]], "material": "weak"}],
  "fixed": {"edges": [0], "polygon": [[0, 8], [10, 8], [10, 11], [0, 11]]},
  "min_block_area": 0
})";

double total_area(const std::vector<Polygon>& blocks) {
  double a = 0.0;
  for (const Polygon& p : blocks) a += signed_area(p);
  return a;
}

std::string error_of(const std::string& text) {
  try {
    parse_model_text(text, "model.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

struct TempDir : dda::test::TempDir {
  TempDir() : dda::test::TempDir("dda_cut_model_") {}
};

test::CommandResult run_cut(const fs::path& model, const fs::path& scene) {
  return run_command(shell_quote(DDA_EXE) + " cut " + shell_quote(model.string()) + " --out " +
                     shell_quote(scene.string()));
}

}  // namespace

TEST_CASE("the test model is valid and read as written", "[cut]") {
  const Model model = parse_model_text(kModel, "model.json");
  const ModelSpec& s = model.spec;
  CHECK(s.domain.size() == 4);
  REQUIRE(s.joint_sets.size() == 1);
  CHECK(s.joint_sets[0].traces.spacing == 2.5);
  CHECK(s.joint_sets[0].joint_material == "bedding");
  CHECK(s.seed == 7);
  REQUIRE(s.joints.size() == 1);
  CHECK(s.joints[0].joint_material == "fault");
  REQUIRE(s.regions.size() == 1);
  CHECK(s.material == "rock");
  CHECK(s.fixed.edges == std::vector<int>{0});
  CHECK(s.fixed.polygon.has_value());
  CHECK(model.scene_settings.contains("control"));
}

TEST_CASE("a bad model is reported at its place in the file", "[cut]") {
  const std::string& m = kModel;
  const std::vector<test::BadInput> bad{
      {"unknown top key", edit(m, "\"joint_sets\":", "\"joint_set\":"), "joint_set",
       {"unknown key", "did you mean \"joint_sets\""}},
      {"domain missing", edit(m, "\"domain\": [[0, 0], [10, 0], [10, 10], [0, 10]],", ""),
       "domain", {"required key is missing"}},
      {"clockwise domain",
       edit(m, "[[0, 0], [10, 0], [10, 10], [0, 10]]", "[[0, 0], [0, 10], [10, 10], [10, 0]]"),
       "domain", {"clockwise"}},
      {"self-crossing domain",
       edit(m, "[[0, 0], [10, 0], [10, 10], [0, 10]]", "[[0, 0], [10, 10], [10, 0], [0, 10]]"),
       "domain", {"crosses itself"}},
      {"zero spacing", edit(m, "\"spacing\": 2.5", "\"spacing\": 0"), "joint_sets[0].spacing",
       {"must be positive"}},
      {"spacing in millimetres", edit(m, "\"spacing\": 2.5", "\"spacing\": 0.00001"),
       "joint_sets[0].spacing", {"lines across the domain", "at most"}},
      {"sets that make a million blocks",  // 100 m^2 / (0.01 m x 0.01 m), 1414 lines each
       edit(m, "{\"dip\": 0, \"spacing\": 2.5, \"offset\": 1.25, \"joint_material\": \"bedding\"}",
            "{\"dip\": 0, \"spacing\": 0.01}, {\"dip\": 90, \"spacing\": 0.01}"),
       "joint_sets", {"cross about 1000000 times", "at most 300000"}},
      {"spacing too large for a double", edit(m, "\"spacing\": 2.5", "\"spacing\": 1e999"),
       "joint_sets[0].spacing", {"too large"}},
      {"negative dip scatter",
       edit(m, "\"offset\": 1.25,", "\"offset\": 1.25, \"dip_scatter\": -1,"),
       "joint_sets[0].dip_scatter", {"must not be negative"}},
      {"negative spacing scatter",
       edit(m, "\"offset\": 1.25,", "\"offset\": 1.25, \"spacing_scatter\": -0.5,"),
       "joint_sets[0].spacing_scatter", {"must not be negative"}},
      {"bridge without trace length",
       edit(m, "\"offset\": 1.25,", "\"offset\": 1.25, \"bridge\": 1,"),
       "joint_sets[0].bridge", {"needs \"trace_length\""}},
      {"unknown set joint material",
       edit(m, "\"joint_material\": \"bedding\"", "\"joint_material\": \"beding\""),
       "joint_sets[0].joint_material", {"unknown joint material \"beding\"", "\"bedding\""}},
      {"second set's spacing",
       edit(m, "\"joint_material\": \"bedding\"}",
            "\"joint_material\": \"bedding\"}, {\"dip\": 90, \"spacing\": -2}"),
       "joint_sets[1].spacing", {"must be positive"}},
      {"unknown set key", edit(m, "\"offset\": 1.25", "\"ofset\": 1.25"), "joint_sets[0].ofset",
       {"unknown key", "did you mean \"offset\""}},
      {"zero-length joint", edit(m, "\"to\": [5, 11]", "\"to\": [5, -1]"), "joints[0].to",
       {"same point"}},
      {"unknown block material", edit(m, "\"material\": \"rock\"", "\"material\": \"granite\""),
       "material", {"unknown material \"granite\"", "\"rock\", \"weak\""}},
      {"unknown region material", edit(m, "\"material\": \"weak\"", "\"material\": \"soft\""),
       "regions[0].material", {"unknown material \"soft\""}},
      {"region not simple",
       edit(m, "[[-1, -1], [5, -1], [5, 11], [-1, 11]]", "[[-1, -1], [5, 11], [5, -1], [-1, 11]]"),
       "regions[0].polygon", {"crosses itself"}},
      {"fixed edge out of range", edit(m, "\"edges\": [0]", "\"edges\": [0, 4]"), "fixed.edges[1]",
       {"edge index 4 is out of range", "4 edges"}},
      {"fixed edge twice", edit(m, "\"edges\": [0]", "\"edges\": [0, 0]"), "fixed.edges[1]",
       {"listed twice"}},
      {"negative smallest area", edit(m, "\"min_block_area\": 0", "\"min_block_area\": -1"),
       "min_block_area", {"must not be negative"}},
      {"negative seed", edit(m, "\"seed\": 7", "\"seed\": -7"), "seed", {"-7"}},
      // The keys shared with scenes are the scene reader's, at the same places.
      {"material young negative", edit(m, "\"young\": 1e9", "\"young\": -1"),
       "materials.rock.young", {"must be positive"}},
      {"control without time step", edit(m, "\"time_step\": 0.001, ", ""), "control.time_step",
       {"required key is missing"}},
      {"no default joint material",
       edit(m, "\"default\": {\"friction_angle\": 35", "\"other\": {\"friction_angle\": 35"),
       "joint_materials.default", {"required key is missing", "\"default\" joint material"}},
      {"joint friction 90", edit(m, "\"friction_angle\": 20", "\"friction_angle\": 90"),
       "joint_materials.bedding.friction_angle", {"less than 90"}},
  };
  for (const test::BadInput& b : bad) {
    INFO(b.name);
    const std::string message = error_of(b.text);
    INFO(message);
    CHECK(test::contains(message, "model.json: " + b.place + ": "));
    for (const std::string& word : b.words) CHECK(test::contains(message, word));
  }
}

TEST_CASE("a model's cut tiles the domain, labels blocks and pairs by what made them", "[cut]") {
  const Model model = parse_model_text(kModel, "model.json");
  const CutModel cut = cut_model(model.spec);
  const std::vector<Polygon>& blocks = cut.cut.blocks;
  REQUIRE(blocks.size() == 10);
  // The corners are exact crossings rounded once to doubles (~1e-16 m each): the areas sum
  // to the domain's to far better than 1e-9.
  CHECK(total_area(blocks) == Approx(100.0).epsilon(1e-9));
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    for (std::size_t j = i + 1; j < blocks.size(); ++j) {
      // Touching is allowed: the overlap test's tolerance, 1e-9 of the domain's size.
      CHECK_FALSE(polygons_overlap(blocks[i], blocks[j], 1e-8));
    }
  }
  int fixed = 0;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const Vec2 c = polygon_moments(blocks[i]).centroid;
    INFO("block " << i << " at (" << c.x() << ", " << c.y() << ")");
    CHECK(cut.materials[i] == (c.x() < 5.0 ? "weak" : "rock"));
    // Fixed: the bottom row (on edge 0, centroid y 0.625) and the top row (y 8.75 to 10,
    // inside the strip y >= 8).
    const bool expect_fixed = c.y() < 1.25 || c.y() > 8.75;
    CHECK(cut.fixed[i] == expect_fixed);
    fixed += cut.fixed[i] ? 1 : 0;
  }
  CHECK(fixed == 4);
  // 13 touching pairs: 8 one above the other (across a bedding trace), 5 side by side
  // (across the fault), every one of a non-default joint material.
  CHECK(cut.cut.adjacency.size() == 13);
  REQUIRE(cut.joints.size() == 13);
  int bedding = 0, fault = 0;
  for (const CutJoint& j : cut.joints) {
    const Vec2 a = polygon_moments(blocks[j.a]).centroid, b = polygon_moments(blocks[j.b]).centroid;
    const bool side_by_side = std::abs(a.y() - b.y()) < 1e-9;  // same row: centroids level
    CHECK(j.joint_material == (side_by_side ? "fault" : "bedding"));
    (side_by_side ? fault : bedding)++;
  }
  CHECK(bedding == 8);
  CHECK(fault == 5);
}

TEST_CASE("a model's scene reads back without a warning and runs", "[cut]") {
  const Model model = parse_model_text(kModel, "model.json");
  const CutModel cut = cut_model(model.spec);
  const CutScene out = cut_scene(model, cut);
  // "spare" is used by no pair: left out, where the scene reader would warn about it.
  CHECK(out.unused_joint_materials == std::vector<std::string>{"spare"});
  const std::string text = scene_text(out.scene);
  const Scene scene = parse_scene_text(text, "cut.json");
  CHECK(scene.warnings.empty());
  REQUIRE(scene.blocks.size() == cut.cut.blocks.size());
  CHECK(scene.joints.size() == 13);
  CHECK(scene.joint_materials.size() == 3);  // default, bedding, fault
  for (std::size_t i = 0; i < scene.blocks.size(); ++i) {
    CHECK(scene.blocks[i].fixed == cut.fixed[i]);
    CHECK(scene.materials[static_cast<std::size_t>(scene.blocks[i].material)].name ==
          cut.materials[i]);
    // Vertices written with full precision: read back bit for bit.
    CHECK(scene.blocks[i].vertices == cut.cut.blocks[i]);
  }
  World world = make_world(scene);
  const RunStats stats = run(world, [](const World&, const RunStats&) { return true; });
  CHECK_FALSE(stats.diverged);
  CHECK(stats.steps == 5);
}

TEST_CASE("a pair's joint material is that of the joints along most of their shared edge",
          "[cut]") {
  // A vertical joint at x = 5 in two pieces, "bedding" below y = 6 and "fault" above: the
  // two halves of the square share 6 m of bedding and 4 m of fault, so their pair is bedding;
  // with the pieces' materials swapped, fault.
  const std::string two_pieces = edit(
      edit(kModel, kFaultJoints,
           "\"joints\": [{\"from\": [5, -1], \"to\": [5, 6], \"joint_material\": \"bedding\"}, "
           "{\"from\": [5, 6], \"to\": [5, 11], \"joint_material\": \"fault\"}]"),
      kSet, "");
  const CutModel cut = cut_model(parse_model_text(two_pieces, "model.json").spec);
  REQUIRE(cut.cut.blocks.size() == 2);
  REQUIRE(cut.cut.adjacency.size() == 1);
  // Lengths of axis-aligned edges between exact corners: exact in doubles.
  CHECK(cut.cut.adjacency[0].shared_length == 10.0);
  REQUIRE(cut.joints.size() == 1);
  CHECK(cut.joints[0].joint_material == "bedding");

  const std::string swapped = edit(edit(two_pieces, "[5, 6], \"joint_material\": \"bedding\"",
                                        "[5, 6], \"joint_material\": \"fault\""),
                                   "[5, 11], \"joint_material\": \"fault\"",
                                   "[5, 11], \"joint_material\": \"bedding\"");
  const CutModel other = cut_model(parse_model_text(swapped, "model.json").spec);
  REQUIRE(other.joints.size() == 1);
  CHECK(other.joints[0].joint_material == "fault");
}

TEST_CASE("each edge of a block has the material of the joint it lies on, or its region's",
          "[cut]") {
  // The test model: the bedding edges (horizontal) are "bedding", those on the fault (x = 5)
  // "fault", whichever pair they separate; the domain's boundary has none. With a region of
  // joint material "spare" over the right column below y = 5, the horizontal edges whose
  // middles lie in it are "spare" (the fault at x = 5 lies outside it).
  for (const bool region : {false, true}) {
    const std::string text =
        region ? edit(kModel, "\"material\": \"weak\"}]",
                      "\"material\": \"weak\"}, {\"polygon\": [[5.5, -1], [11, -1], [11, 5], "
                      "[5.5, 5]], \"joint_material\": \"spare\"}]")
               : kModel;
    const CutModel cut = cut_model(parse_model_text(text, "model.json").spec);
    REQUIRE(cut.cut.blocks.size() == 10);
    REQUIRE(cut.edge_joint_materials.size() == 10);
    int spare = 0;
    for (std::size_t i = 0; i < cut.cut.blocks.size(); ++i) {
      const Polygon& b = cut.cut.blocks[i];
      REQUIRE(cut.edge_joint_materials[i].size() == b.size());
      for (std::size_t k = 0; k < b.size(); ++k) {
        const Vec2 m = 0.5 * (b[k] + b[(k + 1) % b.size()]);
        INFO("block " << i << " edge " << k << " middle " << m.transpose());
        const std::string& name = cut.edge_joint_materials[i][k];
        if (m.x() == 0.0 || m.x() == 10.0 || m.y() == 0.0 || m.y() == 10.0) {
          CHECK(name.empty());
        } else if (m.x() == 5.0) {
          CHECK(name == "fault");
        } else if (region && m.x() > 5.5 && m.y() < 5.0) {
          CHECK(name == "spare");
          ++spare;
        } else {
          CHECK(name == "bedding");
        }
      }
    }
    // Two joints (y = 1.25, 3.75) in the region, each an edge of the block above and below.
    CHECK(spare == (region ? 4 : 0));
  }
}

TEST_CASE("a set's rock bridges are cut with its traces and smeared over the edges they lie on",
          "[cut][bridges]") {
  // The test model's bedding broken into 3 m traces and 1 m bridges of "spare" rock: each
  // line is cut whole (no dead ends), every bedding edge keeps "bedding", and the bridge
  // length each edge holds (share x length), summed along a line over the blocks below it,
  // is the bridges' length inside the domain on that line as joint_set_traces draws them,
  // to round-off (1e-9 m).
  const std::string text = edit(
      kModel, kSet,
      "{\"dip\": 0, \"spacing\": 2.5, \"offset\": 1.25, \"trace_length\": 3, \"bridge\": 1, "
      "\"joint_material\": \"bedding\", \"bridge_material\": \"spare\"}");
  const Model model = parse_model_text(text, "model.json");
  const CutModel cut = cut_model(model.spec);
  CHECK(cut.cut.dead_end_edges == 0);
  REQUIRE(cut.cut.blocks.size() == 10);
  std::map<double, double> smeared;  // line y -> bridge length on the top edges of the blocks below
  for (std::size_t i = 0; i < cut.cut.blocks.size(); ++i) {
    const Polygon& b = cut.cut.blocks[i];
    for (std::size_t k = 0; k < b.size(); ++k) {
      const Vec2 p = b[k], q = b[(k + 1) % b.size()];
      const EdgeBridge& e = cut.edge_bridges[i][k];
      if (p.y() != q.y() || p.y() == 0.0 || p.y() == 10.0) {
        CHECK(e.share == 0.0);
        continue;
      }
      CHECK(cut.edge_joint_materials[i][k] == "bedding");
      if (e.share > 0.0) CHECK(e.material == "spare");
      if (q.x() < p.x()) smeared[p.y()] += e.share * (p - q).norm();  // a top edge runs right to left
    }
  }
  std::vector<JointSegment> bridges;
  const Box box = bounding_box(model.spec.domain);
  joint_set_traces(model.spec.joint_sets[0].traces, box.min, box.max,
                   joint_set_seed(model.spec.seed, 0), &bridges);
  std::map<double, double> drawn;
  for (const JointSegment& g : bridges) {
    if (g.from.y() <= 0.0 || g.from.y() >= 10.0) continue;
    drawn[g.from.y()] += std::max(0.0, std::min(std::max(g.from.x(), g.to.x()), 10.0) -
                                           std::max(std::min(g.from.x(), g.to.x()), 0.0));
  }
  REQUIRE(drawn.size() == 4);
  REQUIRE(smeared.size() == 4);
  for (const auto& [y, length] : drawn) {
    INFO("line y = " << y);
    CHECK(smeared[y] == Approx(length).margin(1e-9));
  }
  // A bridge material needs bridges to give a strength to.
  CHECK(error_of(edit(text, "\"bridge\": 1, ", "")).find(
            "model.json: joint_sets[0].bridge_material: needs \"trace_length\" and a \"bridge\" > 0") == 0);
  CHECK(error_of(edit(text, "\"bridge_material\": \"spare\"", "\"bridge_material\": \"rock\"")).find(
            "model.json: joint_sets[0].bridge_material: unknown joint material \"rock\"") == 0);
}

TEST_CASE("a single joint along a set's trace gives the pair the single joint's material",
          "[cut]") {
  // The fault laid along the bedding trace y = 6.25: the edge both make is the fault's (the
  // higher group: single joints come after the sets).
  const std::string along = edit(kModel, "\"from\": [5, -1], \"to\": [5, 11]",
                                 "\"from\": [-1, 6.25], \"to\": [11, 6.25]");
  const CutModel cut = cut_model(parse_model_text(along, "model.json").spec);
  REQUIRE(cut.cut.blocks.size() == 5);
  int fault = 0;
  for (const CutJoint& j : cut.joints) fault += j.joint_material == "fault" ? 1 : 0;
  CHECK(cut.joints.size() == 4);
  CHECK(fault == 1);
}

TEST_CASE("a concave block takes the region of a point inside it, not of its centroid",
          "[cut]") {
  // An L-shaped domain uncut: one concave block whose centroid (3.89, 3.89) lies in its
  // notch, outside it. The region covers the notch only: the block is not in it.
  std::string l_shape = edit(kModel, "[[0, 0], [10, 0], [10, 10], [0, 10]]",
                             "[[0, 0], [10, 0], [10, 3], [3, 3], [3, 10], [0, 10]]");
  l_shape = edit(l_shape, kSet, "");
  l_shape = edit(l_shape, kFaultJoints, "\"joints\": []");
  l_shape = edit(l_shape, kRegionPolygon, "[[3.5, 3.5], [9, 3.5], [9, 9], [3.5, 9]]");
  const CutModel cut = cut_model(parse_model_text(l_shape, "model.json").spec);
  REQUIRE(cut.cut.blocks.size() == 1);
  const Vec2 c = polygon_moments(cut.cut.blocks[0]).centroid;
  REQUIRE_FALSE(contains_point(cut.cut.blocks[0], c));
  CHECK(cut.materials[0] == "rock");
}

TEST_CASE("dda cut: a bad model exits 2 with its place, a good one writes a scene that runs",
          "[cut][cli]") {
  TempDir dir;
  const fs::path model = dir.path / "model.json", scene = dir.path / "scene.json";

  test::write_file(model, edit(kModel, "\"spacing\": 2.5", "\"spacing\": -1"));
  const test::CommandResult bad = run_cut(model, scene);
  INFO(bad.output);
  CHECK(bad.exit_code == 2);
  CHECK(test::contains(bad.output, "dda: error: " + model.string() +
                                       ": joint_sets[0].spacing: must be positive"));
  CHECK_FALSE(fs::exists(scene));

  test::write_file(model, kModel);
  const test::CommandResult good = run_cut(model, scene);
  INFO(good.output);
  CHECK(good.exit_code == 0);
  CHECK(test::contains(good.output, "10 blocks"));
  CHECK(test::contains(good.output, "blocks by material: rock 5, weak 5"));
  CHECK(test::contains(good.output, "4 fixed blocks"));
  CHECK(test::contains(good.output, "\"spare\" left out"));
  REQUIRE(fs::exists(scene));
  const test::CommandResult ran = run_command(shell_quote(DDA_EXE) + " run " +
                                              shell_quote(scene.string()) + " --out " +
                                              shell_quote((dir.path / "out").string()));
  INFO(ran.output);
  CHECK(ran.exit_code == 0);
  CHECK_FALSE(test::contains(ran.output, "warning"));

  const test::CommandResult unwritable = run_cut(model, dir.path / "no-such-dir" / "scene.json");
  INFO(unwritable.output);
  CHECK(unwritable.exit_code == 1);

  const test::CommandResult none = run_command(shell_quote(DDA_EXE) + " cut");
  CHECK(none.exit_code == 2);
}

TEST_CASE("the example slope model cuts into about 2000 blocks", "[cut]") {
  // models/slope.json: a 200 m x 100 m slope profile and two joint sets, meant to give on the
  // order of 2000 blocks. The bounds are that order of magnitude, loosely.
  const Model model = read_model_file(std::string(DDA_SOURCE_DIR) + "/models/slope.json");
  const CutModel cut = cut_model(model.spec);
  INFO(cut.cut.blocks.size() << " blocks");
  CHECK(cut.cut.blocks.size() > 1500);
  CHECK(cut.cut.blocks.size() < 3000);
  // The domain's area, 200 x 100 less the 80 m x 80 m triangle the face cuts off, to 1e-9
  // relative (corners rounded once over thousands of blocks).
  CHECK(total_area(cut.cut.blocks) == Approx(16800.0).epsilon(1e-9));
  const Scene scene = parse_scene_text(scene_text(cut_scene(model, cut).scene), "slope.json");
  CHECK(scene.warnings.empty());
  CHECK(std::any_of(scene.blocks.begin(), scene.blocks.end(),
                    [](const BlockSpec& b) { return b.fixed; }));
  // Two steps run. The model's max_displacement_ratio (1e-4 of w0 = 100 m: 1 cm a step)
  // keeps the contact search distance (2.5 cm) below the short edges a random cut leaves;
  // at the default 0.01 the narrow phase pairs vertices with edges of the neighbour across
  // such an edge and the first step diverges (see docs/model-format.md).
  Scene two_steps = scene;
  two_steps.control.steps = 2;
  World world = make_world(two_steps);
  const RunStats stats = run(world, [](const World&, const RunStats&) { return true; });
  CHECK_FALSE(stats.diverged);
}

TEST_CASE("the small example slope model cuts into tens of blocks", "[cut]") {
  const Model model = read_model_file(std::string(DDA_SOURCE_DIR) + "/models/small-slope.json");
  const CutModel cut = cut_model(model.spec);
  INFO(cut.cut.blocks.size() << " blocks");
  CHECK(cut.cut.blocks.size() >= 10);
  CHECK(cut.cut.blocks.size() < 100);
  const Scene scene = parse_scene_text(scene_text(cut_scene(model, cut).scene), "small.json");
  CHECK(scene.warnings.empty());
}

TEST_CASE("dda cut warns when no joint set daylights in the slope's faces", "[cut][cli][daylight]") {
  TempDir dir;
  const fs::path model = dir.path / "model.json", scene = dir.path / "scene.json";
  const std::string small = test::read_file(fs::path(DDA_SOURCE_DIR) / "models" / "small-slope.json");
  // As given, its bedding dips 25 degrees out of the 45-degree face: no warning.
  test::write_file(model, small);
  const test::CommandResult daylighting = run_cut(model, scene);
  INFO(daylighting.output);
  REQUIRE(daylighting.exit_code == 0);
  CHECK_FALSE(test::contains(daylighting.output, "daylights"));
  // Turned to dip 25 degrees into the slope (and the cross set steep into it): the warning,
  // naming the face, and the scene is still written.
  test::write_file(model, edit(small, "{\"dip\": 25.0,", "{\"dip\": 155.0,"));
  const test::CommandResult into = run_cut(model, scene);
  INFO(into.output);
  CHECK(into.exit_code == 0);
  CHECK(test::contains(into.output, "warning: no joint set daylights in the slope's faces "
                                    "(domain edges 3)"));
}

TEST_CASE("fixed.depth fixes the blocks lying wholly deeper than it under the free surface",
          "[cut]") {
  // A 10 m square cut into 1 m cells; edges 0, 1 and 3 (bottom, right, left) are fixed, so
  // the top is the free surface. Depth 4: the six rows whose tops lie at y <= 6 are 4 m or
  // more under it (60 cells), and the edges fix the bottom row and the side columns; in all
  // 60 + the side columns' 8 cells above y = 6.
  std::string text = R"({
    "control": {"time_step": 0.001, "steps": 1},
    "materials": {"rock": {"model": "elastic", "density": 2600, "young": 1e9, "poisson": 0.25}},
    "joint_materials": {"default": {"friction_angle": 35, "cohesion": 0, "tensile_strength": 0}},
    "material": "rock",
    "domain": [[0, 0], [10, 0], [10, 10], [0, 10]],
    "joint_sets": [{"dip": 0, "spacing": 1, "offset": 0}, {"dip": 90, "spacing": 1, "offset": 0}],
    "fixed": {"edges": [0, 1, 3], "depth": 4}
  })";
  const Model model = parse_model_text(text, "model.json");
  const CutModel cut = cut_model(model.spec);
  REQUIRE(cut.cut.blocks.size() == 100);
  int fixed = 0;
  for (std::size_t i = 0; i < cut.cut.blocks.size(); ++i) {
    const Box box = bounding_box(cut.cut.blocks[i]);
    const bool deep = box.max.y() <= 6.0 + 1e-9;
    const bool on_edge = box.min.y() < 1e-9 || box.min.x() < 1e-9 || box.max.x() > 10.0 - 1e-9;
    INFO("block " << i << " from (" << box.min.x() << ", " << box.min.y() << ")");
    CHECK(cut.fixed[i] == (deep || on_edge));
    fixed += cut.fixed[i] ? 1 : 0;
  }
  CHECK(fixed == 68);
  // With every edge fixed there is no free surface to measure from.
  text = edit(text, "\"edges\": [0, 1, 3]", "\"edges\": [0, 1, 2, 3]");
  CHECK(error_of(text).find("model.json: fixed.depth: every domain edge is in \"edges\"") == 0);
}

TEST_CASE("a region's joint material goes to the pairs whose shared boundary lies in it",
          "[cut]") {
  // The test model's right column below y = 5: its bedding joints at y = 1.25 and 3.75 (the
  // middles of the shared edges at x = 7.5) become "spare"; the fault at x = 5 is outside
  // (x >= 5.5), and so is every other joint.
  const std::string text =
      edit(kModel, "\"regions\": [{\"polygon\": [[-1, -1], [5, -1], [5, 11], [-1, 11]], \"material\": \"weak\"}]",
           "\"regions\": [{\"polygon\": [[-1, -1], [5, -1], [5, 11], [-1, 11]], \"material\": \"weak\"}, "
           "{\"polygon\": [[5.5, -1], [11, -1], [11, 5], [5.5, 5]], \"joint_material\": \"spare\"}]");
  const Model model = parse_model_text(text, "model.json");
  const CutModel cut = cut_model(model.spec);
  int bedding = 0, fault = 0, spare = 0;
  for (const CutJoint& j : cut.joints) {
    if (j.joint_material == "spare") {
      ++spare;
      const Vec2 a = polygon_moments(cut.cut.blocks[static_cast<std::size_t>(j.a)]).centroid;
      const Vec2 b = polygon_moments(cut.cut.blocks[static_cast<std::size_t>(j.b)]).centroid;
      CHECK(std::min(a.x(), b.x()) > 5.0);                // both in the right column
      CHECK(0.5 * (a.y() + b.y()) < 5.0);                  // below y = 5
    }
    bedding += j.joint_material == "bedding" ? 1 : 0;
    fault += j.joint_material == "fault" ? 1 : 0;
  }
  CHECK(spare == 2);
  CHECK(bedding == 6);
  CHECK(fault == 5);
  // The blocks' materials are the first region's alone (the second gives none).
  CHECK(std::count(cut.materials.begin(), cut.materials.end(), "weak") == 5);
  // A region with neither key is refused at its place.
  CHECK(error_of(edit(kModel, ", \"material\": \"weak\"}]", "}]"))
            .find("model.json: regions[0]: give \"material\"") == 0);
}
