// The paper reproduction's smoke run (verification/paper): `dda_verify_paper --smoke`
// exits 0, prints the report and writes report.md and every CSV, with the rows the plots read;
// bad arguments exit 2. The physics of the treatments is tested elsewhere; this test guards the
// one-command reproduction against breaking.
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"

namespace fs = std::filesystem;

namespace {

using dda::test::CommandResult;
using dda::test::contains;
using dda::test::read_file;
using dda::test::read_lines;

CommandResult run(const std::string& command) { return dda::test::run_command(command); }

}  // namespace

TEST_CASE("paper reproduction: the smoke run writes the report and every CSV", "[paper]") {
  const fs::path out = DDA_PAPER_SMOKE_DIR;
  fs::remove_all(out);
  const CommandResult c =
      run(std::string("'") + DDA_PAPER_EXE + "' --smoke --out '" + out.string() + "'");
  INFO(c.output);
  REQUIRE(c.exit_code == 0);
  CHECK(contains(c.output, "# Paper reproduction"));

  const std::string report = read_file(out / "report.md");
  for (const char* section : {"## Treatments", "## Table 1: the falling octagon",
                              "## Tables 2 and 3: the swinging octagon", "### Energy and swing",
                              "## Speed against error", "### A block sliding down an incline",
                              "### A Mohr-Coulomb specimen compressed through its contacts"}) {
    CHECK(contains(report, section));
  }
  // Every CSV has its header and at least one row.
  for (const char* name : {"falling_scene.csv", "falling_area.csv", "falling_path.csv",
                           "falling_summary.csv", "swinging_diagonals.csv", "swinging_strains.csv",
                           "swinging_energy.csv", "swinging_summary.csv", "speed_spin.csv",
                           "speed_pendulum.csv", "speed_incline.csv", "speed_plastic.csv"}) {
    INFO(name);
    CHECK(read_lines(out / name).size() >= 2);
  }
  // `original` exists from the start: its three Table 1 runs complete.
  int original_completed = 0;
  for (const std::string& line : read_lines(out / "falling_summary.csv")) {
    if (line.rfind("original,", 0) == 0 && contains(line, ",completed,")) ++original_completed;
  }
  CHECK(original_completed == 3);
}

TEST_CASE("paper reproduction: bad arguments exit with code 2", "[paper]") {
  CHECK(run(std::string("'") + DDA_PAPER_EXE + "' --smoke").exit_code == 2);
  CHECK(run(std::string("'") + DDA_PAPER_EXE + "' --out").exit_code == 2);
  CHECK(run(std::string("'") + DDA_PAPER_EXE + "' --what").exit_code == 2);
}
