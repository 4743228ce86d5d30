// OutputWriter: history.csv, the VTK series (vtk/*.vtp + blocks.pvd) and summary.json,
// written from a World built by hand (no solver involved) and read back.
#include <catch2/catch.hpp>

#include "solver/energy.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/output.hpp"
#include "io/vtk_reader.hpp"
#include "kinematics/polygon.hpp"

using namespace dda;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A fresh directory under the system temp dir, removed when the test ends.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& tag) {
    static int counter = 0;
    path = fs::temp_directory_path() /
           ("dda_test_output_" + tag + "_" + std::to_string(getpid()) + "_" +
            std::to_string(counter++));
    fs::remove_all(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<double> csv_numbers(const std::string& line) {
  std::vector<double> out;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(std::strtod(cell.c_str(), nullptr));
  return out;
}

int count_of(const std::string& text, const std::string& needle) {
  int n = 0;
  for (auto pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
  return n;
}

Block make_block(Polygon vertices, double rotation, Vec3 strain, Vec3 local_strain, Vec3 stress,
                 Vec3 velocity) {
  Block b;
  b.initial_vertices = vertices;
  b.vertices = std::move(vertices);
  b.moments = polygon_moments(b.vertices);
  b.initial_area = b.moments.area;
  b.rotation = rotation;
  b.strain = strain;
  b.local_strain = local_strain;
  b.stress = stress;
  b.velocity.head<3>() = velocity;
  b.velocity.tail<3>() = Vec3(1e-6, 2e-6, 3e-6);  // strain rates: not written anywhere
  return b;
}

// Block 0: unit square turned by 90 degrees with strain [1e-3, 0, 0], i.e. local strain
// [0, 1e-3, 0] (stretched along its own y axis).
// Block 1: a fixed triangle with values that have no short decimal form (0.1, 1/3, ...), so
// that only a full-precision write reads back exactly.
World make_test_world(const Scene& scene) {
  World w;
  // One material for both blocks, massless (density 0): the output is checked, not the mass.
  w.materials.push_back(WorldMaterial{});
  w.blocks.push_back(make_block({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, std::numbers::pi / 2, Vec3(1e-3, 0, 0),
                                Vec3(0, 1e-3, 0), Vec3(-1.5e5, 2.0e4 / 3.0, 0.1),
                                Vec3(0.1, -0.2, 1.0 / 7.0)));
  w.blocks.push_back(make_block({{2, 0}, {3, 0}, {2, 1}}, -1.0 / 3.0, Vec3(1.0 / 3.0, -2e-7, 0.7),
                                Vec3(0.1, 2.0 / 3.0, -1e-200),
                                Vec3(1e-300, -1.0 / 3.0, 12345.678901234567),
                                Vec3(0, 0, 0)));
  w.blocks[1].fixed = true;
  w.gravity = scene.gravity;
  w.plane = scene.plane;
  w.control = scene.control;
  w.penalty = 5e11;
  w.w0 = 1.5;
  return w;
}

// Moves every vertex and recomputes the moments, so that later frames differ.
void advance(World& w, int steps, double dt) {
  for (Block& b : w.blocks) {
    for (Vec2& p : b.vertices) p += Vec2(0.1, -0.05);
    b.moments = polygon_moments(b.vertices);
    b.rotation += 0.01;
    b.strain *= 1.1;
  }
  w.step += steps;
  w.time += steps * dt;
}

Scene make_test_scene() {
  Scene scene;
  scene.source = "scenes/test.json";
  scene.control.steps = 20;
  scene.control.output_every = 10;
  return scene;
}

// What record() wrote for one block, in the CSV's column order.
std::vector<double> expected_row(const World& w, int i) {
  const Block& b = w.blocks[i];
  // The energy columns are scene totals (checked against closed forms in test_energy.cpp).
  const EnergyTotals e = scene_energy(w);
  return {double(w.step),     w.time,          double(i),       b.moments.centroid.x(),
          b.moments.centroid.y(), b.rotation,  b.moments.area,  b.strain[0],
          b.strain[1],        b.strain[2],     b.stress[0],     b.stress[1],
          b.stress[2],        b.velocity[0],   b.velocity[1],   b.velocity[2],
          e.kinetic,          e.potential,     e.strain_energy, e.contact_energy,
          w.energy.load_work, w.energy.friction_dissipation, w.energy.plastic_dissipation,
          w.energy.damping_dissipation, w.energy.remainder, w.energy.multiplier_work};
}

// Writes three frames (steps 0, 10, 20) and the summary; keeps a copy of each recorded world.
struct WrittenRun {
  TempDir dir{"run"};
  Scene scene = make_test_scene();
  std::vector<World> recorded;
  RunStats stats;

  WrittenRun() {
    World w = make_test_world(scene);
    OutputWriter out(dir.path, scene);
    for (int k = 0; k < 3; ++k) {
      if (k > 0) advance(w, 10, 0.01);
      out.record(w);
      recorded.push_back(w);
    }
    stats.steps = 20;
    stats.cut_steps = 2;
    stats.iterations = 31;
    stats.wall_time_s = 0.25;
    stats.open_close_total = 50;
    stats.open_close_max = 4;
    stats.contacts_total = 60;
    stats.contacts_max = 5;
    stats.contacts_final = 3;
    stats.cuts_for_displacement = 1;
    stats.cuts_for_penetration = 1;
    stats.smallest_time_step = 0.004;
    stats.largest_time_step = 0.01;
    stats.steps_below_schedule = 2;
    out.finish(w, stats);
  }
};

}  // namespace

TEST_CASE("history.csv has the exact header and one full-precision row per block per record",
          "[output]") {
  WrittenRun run;
  const auto lines = lines_of(read_text(run.dir.path / "history.csv"));
  REQUIRE(lines.size() == 1 + 3 * 2);  // header + 3 records x 2 blocks
  CHECK(lines[0] ==
        "step,time,block,xc,yc,rotation,area,exx,eyy,gxy,sxx,syy,sxy,vx,vy,omega,"
        "kinetic,potential,strain_energy,contact_energy,load_work,friction_dissipation,"
        "plastic_dissipation,damping_dissipation,energy_remainder,multiplier_work");

  // Exact comparison, no tolerance: 17 significant digits identify a double uniquely, so
  // writing the shortest round-trip text and reading with strtod must give back the very same double.
  for (int r = 0; r < 3; ++r) {
    for (int i = 0; i < 2; ++i) {
      INFO("record " << r << ", block " << i);
      CHECK(csv_numbers(lines[1 + 2 * r + i]) == expected_row(run.recorded[r], i));
    }
  }
}

TEST_CASE("summary.json holds the settings, run statistics and final blocks", "[output]") {
  WrittenRun run;
  const json s = json::parse(read_text(run.dir.path / "summary.json"));
  const World& last = run.recorded.back();

  CHECK(s["scene"] == "scenes/test.json");
  const json& set = s["settings"];
  CHECK(set["gravity"] == json::array({0.0, -9.81}));
  CHECK(set["plane"] == "strain");
  CHECK(set["time_step"] == json::array({0.01}));
  CHECK(set["steps"] == 20);
  CHECK(set["end_time"].is_null());
  CHECK(set["max_displacement_ratio"] == 0.01);
  CHECK(set["dynamic_coefficient"] == 1.0);
  CHECK(set["rotation_update"] == "finite_rotation_polar");
  CHECK(set["penalty"] == 5e11);
  CHECK(set["penalty_rule"] == "auto");
  CHECK(set["output_every"] == 10);
  CHECK(set["vtk_format"] == "binary");
  CHECK(set["w0"] == 1.5);

  CHECK(s["wall_time_s"] == 0.25);
  CHECK(s["steps"] == 20);
  CHECK(s["cut_steps"] == 2);
  CHECK(s["iterations"] == 31);
  // Per-step means over the 20 steps: 50 / 20 and 60 / 20, exact in binary to the last bit
  // that matters here (compared to 1e-15).
  CHECK(std::abs(s["open_close_iterations"]["mean"].get<double>() - 2.5) < 1e-15);
  CHECK(s["open_close_iterations"]["max"] == 4);
  CHECK(std::abs(s["contacts"]["mean"].get<double>() - 3.0) < 1e-15);
  CHECK(s["contacts"]["max"] == 5);
  CHECK(s["contacts"]["final"] == 3);
  CHECK(s["penalty_raises"] == 0);  // a key of the format; the penalty is never raised
  CHECK(s["cuts"]["displacement"] == 1);
  CHECK(s["cuts"]["open_close"] == 0);
  CHECK(s["cuts"]["penetration"] == 1);
  CHECK(s["time_steps_taken"]["smallest"] == 0.004);
  CHECK(s["time_steps_taken"]["largest"] == 0.01);
  CHECK(s["time_steps_taken"]["below_schedule"] == 2);
  CHECK(s["end_time"] == last.time);
  CHECK(s["diverged"] == false);
  CHECK(s["message"] == "");

  // nlohmann writes doubles with round-trip precision, so these compare exactly too.
  REQUIRE(s["blocks"].size() == 2);
  for (int i = 0; i < 2; ++i) {
    INFO("block " << i);
    const Block& b = last.blocks[i];
    const json& jb = s["blocks"][i];
    CHECK(jb["index"] == i);
    CHECK(jb["fixed"] == b.fixed);
    REQUIRE(jb["vertices"].size() == b.vertices.size());
    for (std::size_t k = 0; k < b.vertices.size(); ++k) {
      CHECK(jb["vertices"][k] == json::array({b.vertices[k].x(), b.vertices[k].y()}));
    }
    CHECK(jb["centroid"] == json::array({b.moments.centroid.x(), b.moments.centroid.y()}));
    CHECK(jb["rotation"] == b.rotation);
    CHECK(jb["area"] == b.moments.area);
    CHECK(jb["strain"] == json::array({b.strain[0], b.strain[1], b.strain[2]}));
    CHECK(jb["stress"] == json::array({b.stress[0], b.stress[1], b.stress[2]}));
    CHECK(jb["velocity"] == json::array({b.velocity[0], b.velocity[1], b.velocity[2]}));
    CHECK(jb["local_strain"] == json::array({b.local_strain[0], b.local_strain[1], b.local_strain[2]}));
    CHECK(jb["frame_angle"] == b.rotation);
  }
}

TEST_CASE("every record writes a .vtp frame and the .pvd lists all frames", "[output]") {
  WrittenRun run;
  const std::string pvd = read_text(run.dir.path / "blocks.pvd");
  CHECK(pvd.find("type=\"Collection\"") != std::string::npos);
  CHECK(count_of(pvd, "<DataSet ") == 3);
  for (const World& w : run.recorded) {
    char name[32];
    std::snprintf(name, sizeof name, "vtk/step_%06d.vtp", w.step);
    INFO(name);
    // The frame's DataSet line names it, and its timestep attribute reads back as the frame's
    // time exactly (numbers are written as round-trip text).
    const std::size_t at = pvd.find("\" group=\"\" part=\"0\" file=\"" + std::string(name) + "\"");
    REQUIRE(at != std::string::npos);
    const std::size_t open = pvd.rfind("timestep=\"", at);
    REQUIRE(open != std::string::npos);
    const std::size_t value = open + std::string("timestep=\"").size();
    CHECK(std::stod(pvd.substr(value, at - value)) == w.time);

    REQUIRE(fs::exists(run.dir.path / name));
    const std::string vtp = read_text(run.dir.path / name);
    CHECK(vtp.find("NumberOfPoints=\"7\"") != std::string::npos);  // 4 + 3 vertices
    CHECK(vtp.find("NumberOfPolys=\"2\"") != std::string::npos);
    for (const char* array : {"block", "fixed", "area", "rotation", "stress", "strain", "velocity"}) {
      CHECK(vtp.find("Name=\"" + std::string(array) + "\"") != std::string::npos);
    }
    // The default binary frame, read back: every block's polygon and cell data, exactly
    // (the file holds the doubles' bits).
    const VtkPolyData frame = read_vtp(run.dir.path / name);
    REQUIRE(frame.polys.has_value());
    REQUIRE(frame.polys->size() == w.blocks.size());
    for (std::size_t i = 0; i < w.blocks.size(); ++i) {
      const Block& b = w.blocks[i];
      CHECK(frame.polygon(i) == b.vertices);
      CHECK(frame.find_cell_array("area")->at(i) == b.moments.area);
      CHECK(frame.find_cell_array("fixed")->at(i) == (b.fixed ? 1.0 : 0.0));
      for (int k = 0; k < 3; ++k) CHECK(frame.find_cell_array("stress")->at(i, k) == b.stress[k]);
    }
    CHECK(frame.find_cell_array("velocity")->component_names ==
          std::vector<std::string>{"vx", "vy", "omega"});
  }
}

TEST_CASE("vtk_format ascii writes the frames as text, holding what the binary ones hold",
          "[output]") {
  TempDir binary_dir("binary"), ascii_dir("ascii");
  Scene scene = make_test_scene();
  World w = make_test_world(scene);
  advance(w, 10, 0.01);
  OutputWriter(binary_dir.path, scene).record(w);
  scene.control.vtk_binary = false;
  OutputWriter(ascii_dir.path, scene).record(w);
  for (const char* name : {"vtk/step_000010.vtp", "vtk/contacts_000010.vtp"}) {
    INFO(name);
    const std::string text = read_text(ascii_dir.path / name);
    CHECK(text.find("format=\"ascii\"") != std::string::npos);
    CHECK(text.find("AppendedData") == std::string::npos);
    CHECK(read_text(binary_dir.path / name).find("compressor=\"vtkZLibDataCompressor\"") !=
          std::string::npos);
    // The ASCII frame read back and written as binary is the binary frame, byte for byte:
    // the same numbers, exactly.
    CHECK(vtp_file(read_vtp(ascii_dir.path / name), VtkEncoding::Binary) ==
          read_text(binary_dir.path / name));
  }
}

TEST_CASE("recording the same step twice keeps one frame in the index", "[output]") {
  TempDir dir("repeat");
  const Scene scene = make_test_scene();
  World w = make_test_world(scene);
  OutputWriter out(dir.path, scene);
  out.record(w);
  out.record(w);
  CHECK(count_of(read_text(dir.path / "blocks.pvd"), "<DataSet ") == 1);
  CHECK(lines_of(read_text(dir.path / "history.csv")).size() == 1 + 2 * 2);
}

TEST_CASE("summary.json reports a user penalty, an end time and a divergence", "[output]") {
  TempDir dir("user");
  Scene scene = make_test_scene();
  scene.plane = PlaneMode::Stress;
  scene.control.steps.reset();
  scene.control.end_time = 2.5;
  scene.control.penalty = 1e9;
  scene.control.time_steps = {0.01, 0.02};
  scene.control.rotation_update = RotationUpdate::LocalFrameAsPrinted;
  World w = make_test_world(scene);
  w.penalty = 1e9;
  RunStats stats;
  stats.diverged = true;
  stats.message = "vertex moved too far";
  OutputWriter out(dir.path, scene);
  out.finish(w, stats);  // no record(): a run that failed before its first frame

  const json s = json::parse(read_text(dir.path / "summary.json"));
  CHECK(s["settings"]["plane"] == "stress");
  CHECK(s["settings"]["steps"].is_null());
  CHECK(s["settings"]["end_time"] == 2.5);
  CHECK(s["settings"]["time_step"] == json::array({0.01, 0.02}));
  CHECK(s["settings"]["penalty"] == 1e9);
  CHECK(s["settings"]["penalty_rule"] == "user");
  CHECK(s["settings"]["rotation_update"] == "local_frame_as_printed");
  CHECK(s["diverged"] == true);
  CHECK(s["message"] == "vertex moved too far");
  CHECK(count_of(read_text(dir.path / "blocks.pvd"), "<DataSet ") == 0);
}

TEST_CASE("OutputWriter names the path it cannot write to", "[output]") {
  TempDir dir("blocked");
  fs::create_directories(dir.path);
  const fs::path blocker = dir.path / "a_file";
  std::ofstream(blocker) << "not a directory\n";
  const Scene scene = make_test_scene();
  // A directory cannot be created under a regular file.
  CHECK_THROWS_WITH(OutputWriter(blocker / "out", scene), Catch::Contains(blocker.string()));
}
