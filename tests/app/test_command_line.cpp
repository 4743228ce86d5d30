// The command line itself (src/app/main.cpp), through the real executable: a line the parser
// refuses is bad input (exit 2, one message naming the bad argument), never CLI11's own exit
// codes; --help and --version exit 0; an empty --out is refused before anything is written.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"

namespace {

dda::test::CommandResult dda_with(const std::string& args) {
  return dda::test::run_command(dda::test::shell_quote(DDA_EXE) + " " + args);
}

}  // namespace

TEST_CASE("a command line the parser refuses exits 2 naming the bad argument", "[cli]") {
  struct Case {
    std::string args;
    std::vector<std::string> words;  // the message must name these
  };
  const std::vector<Case> cases = {
      {"", {"no command given", "run, material-point, fos, cut"}},
      {"frobnicate", {"unknown command 'frobnicate'", "run, material-point, fos, cut"}},
      {"run a.json b.json", {"not expected", "b.json"}},
      {"run --out", {"--out", "missing"}},
      {"run --frobnicate", {"not expected", "--frobnicate"}},
      {"fos a.json --tolerance 5", {"--tolerance", "5"}},
      // Numbers must be finite: CLI11's own checks passed "nan" (every comparison with it
      // is false) and "inf" for a positive number, and `dda fos --max-factor nan --method
      // limit-analysis` then ran for ever (found by verification/fuzz under ASan).
      {"fos a.json --max-factor nan", {"--max-factor", "nan is not a finite number"}},
      {"fos a.json --min-factor -nan", {"--min-factor", "-nan is not a finite number"}},
      {"fos a.json --tolerance NaN", {"--tolerance", "NaN is not a finite number"}},
      {"fos a.json --trial-time inf", {"--trial-time", "inf is not a finite number"}},
      {"fos a.json --failure-displacement 1e999", {"--failure-displacement", "not a finite"}},
      {"fos a.json --trial-time 0", {"--trial-time", "0 is not positive"}},
      {"fos a.json --seismic-coefficient 0x", {"--seismic-coefficient", "0x is not a number"}},
      {"fos a.json --dynamic-coefficient 1.5", {"--dynamic-coefficient", "not in range 0 to 1"}},
      {"material-point --out", {"--out", "missing"}},
  };
  for (const Case& c : cases) {
    INFO("dda " << c.args);
    const dda::test::CommandResult r = dda_with(c.args);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.rfind("dda: error: ", 0) == 0);
    // One message, one line.
    CHECK(r.output.find('\n') == r.output.size() - 1);
    for (const std::string& w : c.words) CHECK(dda::test::contains(r.output, w));
  }
}

TEST_CASE("the version flag prints the version and the help flag the commands, both exit 0", "[cli]") {
  const dda::test::CommandResult version = dda_with("--version");
  CHECK(version.exit_code == 0);
  CHECK(version.output == std::string("dda ") + DDA_VERSION_FOR_TESTS + "\n");
  const dda::test::CommandResult help = dda_with("--help");
  CHECK(help.exit_code == 0);
  for (const char* command : {"run", "material-point", "fos", "cut"}) {
    CHECK(dda::test::contains(help.output, command));
  }
  CHECK(dda_with("run --help").exit_code == 0);
}

TEST_CASE("an empty --out is refused for every command, and nothing is written", "[cli]") {
  dda::test::TempDir dir("dda-cli-");
  const std::string scene = dda::test::shell_quote(std::string(DDA_SOURCE_DIR) + "/scenes/free_fall.json");
  const std::string model = dda::test::shell_quote(std::string(DDA_SOURCE_DIR) + "/models/slope.json");
  const std::string spec = dda::test::shell_quote(
      std::string(DDA_SOURCE_DIR) + "/verification/constitutive/specs/dp_simple_shear.json");
  for (const std::string& args :
       {"run " + scene, "fos " + scene, "cut " + model, "material-point " + spec}) {
    INFO("dda " << args << " --out ''");
    // Run inside the temporary directory: "" used to mean the current directory.
    const dda::test::CommandResult r = dda::test::run_command(
        "cd " + dda::test::shell_quote(dir.path.string()) + " && " +
        dda::test::shell_quote(DDA_EXE) + " " + args + " --out ''");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(dda::test::contains(r.output, "--out is empty"));
    CHECK(std::filesystem::is_empty(dir.path));
  }
}
