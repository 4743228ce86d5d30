// Monitoring points (scene key `monitors`, DIR/monitors.csv): through the real
// command line, on motions with closed forms. The contract's header is checked verbatim.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"

using namespace dda::test;

namespace {

struct MonitorRow {
  int step = 0;
  double time = 0.0, x = 0.0, y = 0.0, ux = 0.0, uy = 0.0, vx = 0.0, vy = 0.0;
};

// The rows of monitors.csv by monitor name, in file order.
std::map<std::string, std::vector<MonitorRow>> read_monitors(const std::filesystem::path& csv) {
  const std::vector<std::string> lines = read_lines(csv);
  REQUIRE(!lines.empty());
  CHECK(lines[0] == "step,time,monitor,x,y,ux,uy,vx,vy");
  std::map<std::string, std::vector<MonitorRow>> out;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    std::istringstream in(lines[k]);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    REQUIRE(cells.size() == 9);
    MonitorRow r;
    r.step = std::stoi(cells[0]);
    r.time = std::stod(cells[1]);
    r.x = std::stod(cells[3]);
    r.y = std::stod(cells[4]);
    r.ux = std::stod(cells[5]);
    r.uy = std::stod(cells[6]);
    r.vx = std::stod(cells[7]);
    r.vy = std::stod(cells[8]);
    out[cells[2]].push_back(r);
  }
  return out;
}

std::map<std::string, std::vector<MonitorRow>> run_scene(const std::string& scene) {
  TempDir dir("dda_monitors_");
  write_file(dir.path / "scene.json", scene);
  const CommandResult result = run_command(shell_quote(DDA_EXE) + " run " +
                                           shell_quote((dir.path / "scene.json").string()) +
                                           " --out " + shell_quote((dir.path / "out").string()));
  INFO(result.output);
  REQUIRE(result.exit_code == 0);
  return read_monitors(dir.path / "out" / "monitors.csv");
}

}  // namespace

TEST_CASE("a monitor on a falling block follows g t^2 / 2, and one on a fixed block stays",
          "[monitors][cli]") {
  // DDA's step is exact for a constant acceleration (d = v0 dt + g dt^2 / 2, v = 2 d / dt -
  // v0), and uniform gravity strains no block, so every row matches the closed form to
  // round-off: 1e-12 m on displacements of ~1 m (positions are summed over 50 steps of
  // increments of ~1e-2 m, each exact to ~1e-17 m). Ratio 0.2: the block's step limit,
  // 0.2 x 0.5 m, stays above the last step's fall g dt^2 x 50.5 = 5 cm, so no step is cut
  // and every row lands on a multiple of dt.
  const std::string scene = R"json({
    "gravity": [0, -9.81],
    "control": {"time_step": 0.01, "steps": 50, "output_every": 10,
                "max_displacement_ratio": 0.2},
    "materials": {"rock": {"model": "elastic", "density": 2500, "young": 1e9, "poisson": 0.2}},
    "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
    "blocks": [
      {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock"},
      {"vertices": [[10, -5], [12, -5], [12, -4], [10, -4]], "material": "rock", "fixed": true}
    ],
    "monitors": [{"name": "corner", "point": [0.8, 0.9]}, {"name": "base", "point": [11, -4.5]}]
  })json";
  const auto rows = run_scene(scene);
  REQUIRE(rows.at("corner").size() == 6);  // steps 0, 10, ..., 50
  REQUIRE(rows.at("base").size() == 6);
  for (const MonitorRow& r : rows.at("corner")) {
    INFO("step " << r.step);
    CHECK(r.time == Approx(0.01 * r.step).margin(1e-12));
    CHECK(r.ux == Approx(0.0).margin(1e-12));
    CHECK(r.uy == Approx(-0.5 * 9.81 * r.time * r.time).margin(1e-12));
    CHECK(r.x == Approx(0.8 + r.ux).margin(1e-12));
    CHECK(r.y == Approx(0.9 + r.uy).margin(1e-12));
    CHECK(r.vx == Approx(0.0).margin(1e-12));
    CHECK(r.vy == Approx(-9.81 * r.time).margin(1e-12));
  }
  for (const MonitorRow& r : rows.at("base")) {
    CHECK(r.x == 11.0);
    CHECK(r.y == -4.5);
    CHECK(r.ux == 0.0);
    CHECK(r.vy == 0.0);
  }
}

TEST_CASE("a monitor on a spinning block turns with it at omega |r|", "[monitors][cli]") {
  // A free square spinning at 2 rad/s, no gravity: each step turns it by r0 = omega dt (no
  // force couples to the spin), and finite_rotation places points by the exact rotation,
  // (the displacement ratio lets a corner move 5 cm a step, 2.8 cm needed, so no step is
  // cut), so after 1 s the monitor is at c + R(2 rad) r0, r0 its start offset from the centroid,
  // moving at omega (-y, x) of its offset. Exact but for round-off (measured 0 m and
  // 4e-15 m/s): 1e-12. Shi's inertia, so that the block stays rigid (the pseudo-rigid
  // inertia would stretch it by rho omega^2 a^2 / 12 E = 3e-6, moving the monitor by 2 um).
  const std::string scene = R"json({
    "gravity": [0, 0],
    "control": {"time_step": 0.01, "end_time": 1.0, "output_every": 1000,
                "max_displacement_ratio": 0.05, "inertia": "shi"},
    "materials": {"rock": {"model": "elastic", "density": 2500, "young": 1e9, "poisson": 0.2}},
    "blocks": [{"vertices": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "material": "rock",
                "velocity": [0, 0, 2]}],
    "monitors": [{"name": "edge", "point": [0.6, 0.3]}]
  })json";
  const auto rows = run_scene(scene);
  REQUIRE(rows.at("edge").size() == 2);
  const MonitorRow& end = rows.at("edge").back();
  REQUIRE(end.time == Approx(1.0));
  const double angle = 2.0 * end.time;
  const double x = 0.6 * std::cos(angle) - 0.3 * std::sin(angle);
  const double y = 0.6 * std::sin(angle) + 0.3 * std::cos(angle);
  CHECK(end.x == Approx(x).margin(1e-12));
  CHECK(end.y == Approx(y).margin(1e-12));
  CHECK(end.ux == Approx(x - 0.6).margin(1e-12));
  CHECK(end.vx == Approx(-2.0 * y).margin(1e-12));
  CHECK(end.vy == Approx(2.0 * x).margin(1e-12));
}

TEST_CASE("a scene without monitors writes no monitors.csv", "[monitors][cli]") {
  TempDir dir("dda_no_monitors_");
  write_file(dir.path / "scene.json", R"json({
    "control": {"time_step": 0.01, "steps": 2},
    "materials": {"rock": {"model": "elastic", "density": 2500, "young": 1e9, "poisson": 0.2}},
    "blocks": [{"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock"}]
  })json");
  const CommandResult result = run_command(shell_quote(DDA_EXE) + " run " +
                                           shell_quote((dir.path / "scene.json").string()) +
                                           " --out " + shell_quote((dir.path / "out").string()));
  REQUIRE(result.exit_code == 0);
  CHECK(std::filesystem::exists(dir.path / "out" / "history.csv"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "out" / "monitors.csv"));
}
