// `dda sweep SWEEP.json --out DIR` on one process: a grid of a block's friction angle on a
// plane, each variant's factor against the closed form tan(phi) / tan(dip), the variant's
// folder and its row in sweep.csv; a place the scene lacks is exit 2 naming it, before any
// variant runs.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"
#include "support/plane_block_scene.hpp"

namespace fs = std::filesystem;
using dda::test::run_command;
using dda::test::shell_quote;

namespace {

std::vector<std::vector<std::string>> csv_rows(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

dda::test::CommandResult sweep(const fs::path& file, const fs::path& out) {
  return run_command(shell_quote(DDA_EXE) + " sweep " + shell_quote(file.string()) + " --out " +
                     shell_quote(out.string()));
}

}  // namespace

TEST_CASE("dda sweep runs a grid of friction angles and finds each variant's factor",
          "[sweep][cli]") {
  const dda::test::TempDir dir("dda_sweep_");
  dda::test::write_file(dir.path / "plane.json", dda::test::plane_block_scene(30.0, 32.0).dump());
  const nlohmann::json spec = {
      {"scene", "plane.json"},  // beside the sweep file
      {"command", "fos"},
      {"fos", {{"jobs", 1}, {"skip_limit_analysis", true}}},
      {"grid", {{"/joint_materials/default/friction_angle", {35, 40}}}}};
  dda::test::write_file(dir.path / "sweep.json", spec.dump());
  const dda::test::CommandResult r = sweep(dir.path / "sweep.json", dir.path / "out");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const auto rows = csv_rows(dir.path / "out" / "sweep.csv");
  REQUIRE(rows.size() == 3);
  CHECK(rows[0] == std::vector<std::string>{"variant", "\"/joint_materials/default/friction_angle\"",
                                            "exit_code", "status", "factor_of_safety", "last_stable",
                                            "first_failing", "probability_of_failure",
                                            "samples_judged"});
  const double phis[] = {35.0, 40.0};
  for (int v = 0; v < 2; ++v) {
    const auto& row = rows[static_cast<std::size_t>(v) + 1];
    REQUIRE(row.size() == 9);
    CHECK(row[0] == "variant-00" + std::to_string(v));
    CHECK(std::stod(row[1]) == phis[v]);
    CHECK(row[2] == "0");
    CHECK(row[3] == "done");
    // The bracket holds the closed form, less the verdict's resolution: a trial resolves
    // accelerations of 0.002 g, and the block at F accelerates at g sin(30) (1 - Fc / F), so a
    // stable verdict may stand up to 0.004 F (0.006 here) above Fc; 0.01 allows it.
    const double closed = std::tan(phis[v] * M_PI / 180.0) / std::tan(M_PI / 6.0);
    const double last_stable = std::stod(row[5]), first_failing = std::stod(row[6]);
    CHECK(last_stable <= closed + 0.01);
    CHECK(first_failing >= closed);
    CHECK(first_failing - last_stable <= 0.01 + 1e-12);  // the search's tolerance
    // The variant's folder: its scene with the value put in, and its fos report.
    const fs::path folder = dir.path / "out" / ("variant-00" + std::to_string(v));
    const nlohmann::json scene = nlohmann::json::parse(std::ifstream(folder / "scene.json"));
    CHECK(scene["joint_materials"]["default"]["friction_angle"] == phis[v]);
    const nlohmann::json report = nlohmann::json::parse(std::ifstream(folder / "report.json"));
    CHECK(report["factor_of_safety"].get<double>() == std::stod(row[4]));
  }
}

TEST_CASE("dda sweep refuses a place the scene lacks before running any variant", "[sweep][cli]") {
  const dda::test::TempDir dir("dda_sweep_bad_");
  dda::test::write_file(dir.path / "plane.json", dda::test::plane_block_scene(30.0, 32.0).dump());
  nlohmann::json spec = {{"scene", "plane.json"},
                         {"command", "fos"},
                         {"list", {{{"/joint_materials/default/friction_angle", 35}},
                                   {{"/joint_materials/default/friction_angle", -5}}}}};
  dda::test::write_file(dir.path / "sweep.json", spec.dump());
  // A value the scene refuses: the scene reader's message, with the variant named.
  dda::test::CommandResult r = sweep(dir.path / "sweep.json", dir.path / "out");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("variant-001") && Catch::Contains("friction_angle"));
  CHECK_FALSE(fs::exists(dir.path / "out" / "variant-000"));
  // A misspelt place.
  spec["list"] = {{{"/joint_materials/default/friction_angel", 35}}};
  dda::test::write_file(dir.path / "sweep.json", spec.dump());
  r = sweep(dir.path / "sweep.json", dir.path / "out");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("sweep.json: variant-000") &&
                           Catch::Contains("/joint_materials/default/friction_angel"));
  CHECK_FALSE(fs::exists(dir.path / "out" / "sweep.csv"));
}
