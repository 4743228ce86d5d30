// A run with bolts writes bolts.csv (a row per bolt per output step), the bolts' VTK series
// (vtk/bolts_NNNNNN.vtp, a line per bolt with its force, bolts.pvd) and their end state in
// summary.json; a run without bolts writes none of these (docs/output-format.md).
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"
#include "io/output.hpp"
#include "io/vtk_reader.hpp"

namespace fs = std::filesystem;
using dda::test::run_command;
using dda::test::shell_quote;

TEST_CASE("a run with bolts writes bolts.csv, the bolts' VTK series and their end state, and one "
          "without writes none",
          "[bolts][output]") {
  const dda::test::TempDir dir("dda_bolt_output_");
  const fs::path scene = fs::path(DDA_SOURCE_DIR) / "scenes" / "bolted_block.json";
  const fs::path out = dir.path / "out";
  const dda::test::CommandResult r = run_command(shell_quote(DDA_EXE) + " run " +
                                                 shell_quote(scene.string()) + " --out " +
                                                 shell_quote(out.string()));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  // The scene runs 500 steps with output every 50: 11 output steps, one bolt.
  const std::string csv = dda::test::read_file(out / "bolts.csv");
  CHECK(csv.rfind("step,time,bolt,force,plastic_extension,broken,length\n", 0) == 0);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 1 + 11);
  const std::string frame = dda::test::read_file(out / "vtk" / "bolts_000500.vtp");
  CHECK(frame.find("NumberOfPoints=\"2\"") != std::string::npos);
  CHECK(frame.find("NumberOfLines=\"1\"") != std::string::npos);
  CHECK(frame.find("Name=\"force\"") != std::string::npos);
  const std::string pvd = dda::test::read_file(out / "bolts.pvd");
  CHECK(std::count(pvd.begin(), pvd.end(), '\n') > 11);
  CHECK(pvd.find("vtk/bolts_000500.vtp") != std::string::npos);
  const nlohmann::json summary = nlohmann::json::parse(dda::test::read_file(out / "summary.json"));
  REQUIRE(summary["bolts"].size() == 1);
  CHECK(summary["bolts"][0]["name"] == "B1");
  // The bolt holds the block: its force is what the last bolts.csv row says.
  const double force = summary["bolts"][0]["force"].get<double>();
  CHECK(force > 0.0);
  CHECK(csv.find(",B1," + dda::format_full_precision(force) + ",") != std::string::npos);
  // The last frame, binary by default, read back: the same force, bit for bit.
  const dda::VtkPolyData bolts = dda::read_vtp(out / "vtk" / "bolts_000500.vtp");
  REQUIRE(bolts.lines.has_value());
  CHECK(bolts.lines->connectivity == std::vector<std::int64_t>{0, 1});
  CHECK(bolts.find_cell_array("force")->values == std::vector<double>{force});

  // Without bolts: none of the files, and no "bolts" key.
  const fs::path plain = dir.path / "plain";
  const dda::test::CommandResult p = run_command(
      shell_quote(DDA_EXE) + " run " +
      shell_quote((fs::path(DDA_SOURCE_DIR) / "scenes" / "incline.json").string()) + " --out " +
      shell_quote(plain.string()));
  REQUIRE(p.exit_code == 0);
  CHECK_FALSE(fs::exists(plain / "bolts.csv"));
  CHECK_FALSE(fs::exists(plain / "bolts.pvd"));
  CHECK_FALSE(fs::exists(plain / "vtk" / "bolts_000000.vtp"));
  CHECK_FALSE(nlohmann::json::parse(dda::test::read_file(plain / "summary.json")).contains("bolts"));
}
