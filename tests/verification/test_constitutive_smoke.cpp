// The iso-error maps' smoke run (verification/constitutive):
// `dda_verify_constitutive --smoke` exits 0, prints the report and writes report.md, maps.csv
// and one CSV per map with every grid point, no failed return, and the start on the surface
// (error 0 at the zero increment and at every elastic point); bad arguments exit 2. It guards
// the one-command run; the maps' numbers themselves are held by
// tests/verification/test_constitutive_numbers.cpp, and check_projection.py (ctest constitutive_smoke_plot)
// recomputes the smoke run's plastic points independently.
#include <catch2/catch.hpp>
#include <cmath>
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

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

}  // namespace

TEST_CASE("iso-error maps: the smoke run writes the report and every map", "[constitutive]") {
  const fs::path out = DDA_CONSTITUTIVE_SMOKE_DIR;
  fs::remove_all(out);
  const CommandResult c =
      run(std::string("'") + DDA_CONSTITUTIVE_EXE + "' --smoke --out '" + out.string() + "'");
  INFO(c.output);
  REQUIRE(c.exit_code == 0);
  CHECK(contains(c.output, "# Iso-error maps of the return maps"));

  const std::string report = read_file(out / "report.md");
  for (const char* section : {"## Maximum errors", "## What the maps show",
                              "## Shrinking the worst increment", "## Runtime"}) {
    CHECK(contains(report, section));
  }

  // maps.csv names the maps; the first field is the quoted name.
  const std::vector<std::string> maps = read_lines(out / "maps.csv");
  REQUIRE(maps.size() >= 2);
  int mohr_coulomb = 0, drucker_prager = 0;
  for (std::size_t i = 1; i < maps.size(); ++i) {
    const std::string quoted = maps[i].substr(0, maps[i].find(','));
    REQUIRE(quoted.size() > 2);
    const std::string name = quoted.substr(1, quoted.size() - 2);
    INFO(name);
    mohr_coulomb += name.rfind("mc_", 0) == 0;
    drucker_prager += name.rfind("dp_", 0) == 0;
    CHECK(contains(report, "`" + name + "`"));
    // The smoke grid: 5 x 5 points, every one converged, error 0 at the zero increment.
    const std::vector<std::string> rows = read_lines(out / (name + ".csv"));
    REQUIRE(rows.size() == 26);
    CHECK(contains(rows[0], "x,y,exx,eyy,gxy,"));
    int plastic = 0;
    for (std::size_t r = 1; r < rows.size(); ++r) {
      const std::vector<std::string> f = fields(rows[r]);
      REQUIRE(f.size() == 19);
      CHECK(f[18] == "ok");
      const double error = std::stod(f[13]);
      CHECK(std::isfinite(error));
      CHECK(error >= 0.0);
      // The zero increment, and any elastic trial (the straight path stayed inside the convex
      // domain, so the reference's last sub-increment is the one call's own computation).
      if (f[0] == "0" && f[1] == "0") CHECK(error == 0.0);
      if (f[14] == "elastic") CHECK(error == 0.0);
      plastic += f[14] != "elastic";
    }
    CHECK(plastic > 0);  // each map reaches the surface somewhere
  }
  CHECK(mohr_coulomb >= 2);
  CHECK(drucker_prager >= 2);
}

TEST_CASE("iso-error maps: bad arguments exit with code 2", "[constitutive]") {
  CHECK(run(std::string("'") + DDA_CONSTITUTIVE_EXE + "' --smoke").exit_code == 2);
  CHECK(run(std::string("'") + DDA_CONSTITUTIVE_EXE + "' --out").exit_code == 2);
  CHECK(run(std::string("'") + DDA_CONSTITUTIVE_EXE + "' --what").exit_code == 2);
}
