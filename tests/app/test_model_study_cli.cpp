// The slope engineer's model end to end: models/small-slope-bolted.json (water, a monitor,
// fixed base and depth, a consolidation, a lift excavated at the toe, a row of face bolts)
// cut by `dda cut` and its factor found by `dda fos`, with no hand edit of the scene; and the
// same model without its bolts: the bolts raise the factor (support adds resistance).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_helpers.hpp"

namespace fs = std::filesystem;
using dda::test::run_command;
using dda::test::shell_quote;

namespace {

// Under AddressSanitizer the strength-reduction searches take some 30 times as long (the
// bolted model's alone 18 min): there the test asks the limit analysis only, which runs the
// same consolidation, excavation and water.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

// Cuts `model` into DIR/scene.json (once) and runs dda fos on it with `options` into
// DIR/`out`; its report.
nlohmann::json cut_and_fos(const fs::path& model, const fs::path& dir, const std::string& out,
                           const std::string& options) {
  const fs::path scene = dir / "scene.json";
  if (!fs::exists(scene)) {
    const dda::test::CommandResult cut = run_command(shell_quote(DDA_EXE) + " cut " +
                                                     shell_quote(model.string()) + " --out " +
                                                     shell_quote(scene.string()));
    INFO(cut.output);
    REQUIRE(cut.exit_code == 0);
  }
  const dda::test::CommandResult fos = run_command(shell_quote(DDA_EXE) + " fos " +
                                                   shell_quote(scene.string()) + " --out " +
                                                   shell_quote((dir / out).string()) + " " + options);
  INFO(fos.output);
  REQUIRE(fos.exit_code == 0);
  return nlohmann::json::parse(std::ifstream(dir / out / "report.json"));
}

}  // namespace

TEST_CASE("the example model goes from profile to a bolted, excavated, wet factor of safety, "
          "and its bolts raise it",
          "[cut][fos][bolts][excavation]") {
  const dda::test::TempDir dir("dda_model_study_cli_");
  const fs::path model = fs::path(DDA_SOURCE_DIR) / "models" / "small-slope-bolted.json";
  fs::create_directories(dir.path / "bolted");
  const nlohmann::json bolted_la =
      cut_and_fos(model, dir.path / "bolted", "la", "--method limit-analysis");
  // The scene the cut wrote holds the study.
  const nlohmann::json scene = nlohmann::json::parse(std::ifstream(dir.path / "bolted" / "scene.json"));
  CHECK(scene.contains("water"));
  CHECK(scene.contains("monitors"));
  CHECK(scene["bolts"].size() >= 3);
  CHECK(scene["stages"][1]["excavate"].size() >= 1);

  nlohmann::json unbolted = nlohmann::json::parse(std::ifstream(model));
  unbolted.erase("bolt_patterns");
  fs::create_directories(dir.path / "unbolted");
  const fs::path plain = dir.path / "unbolted" / "model.json";
  std::ofstream(plain) << unbolted.dump();
  const nlohmann::json plain_la =
      cut_and_fos(plain, dir.path / "unbolted", "la", "--method limit-analysis");
  // The limit analysis of the consolidated, excavated, wet slope: the face block alone on its
  // wet bedding without bolts (1.237; dry, tan 30 / tan 25 = 1.238), 1.346 with them. Exact
  // linear programs on the same consolidated contacts: 0.05 is far beyond their round-off
  // and far below the bolts' 0.11.
  const double bolted = bolted_la["limit_analysis"]["factor"].get<double>();
  const double without = plain_la["limit_analysis"]["factor"].get<double>();
  INFO("limit analysis: bolted " << bolted << ", without bolts " << without);
  CHECK(bolted > without + 0.05);
  CHECK(std::abs(without - std::tan(30.0 * M_PI / 180.0) / std::tan(25.0 * M_PI / 180.0)) < 0.01);
  if (kSanitized) return;
  // The strength reduction (about 40 s for the bolted model on one thread).
  const nlohmann::json bolted_sr = cut_and_fos(model, dir.path / "bolted", "fos", "--jobs 1");
  const nlohmann::json plain_sr = cut_and_fos(plain, dir.path / "unbolted", "fos", "--jobs 1");
  REQUIRE(bolted_sr["found"].get<bool>());
  REQUIRE(plain_sr["found"].get<bool>());
  const double bolted_f = bolted_sr["factor_of_safety"].get<double>();
  const double without_f = plain_sr["factor_of_safety"].get<double>();
  INFO("strength reduction: bolted " << bolted_f << ", without bolts " << without_f);
  // Above by more than the two searches' brackets (0.0078 each, from their tolerance 0.01):
  // measured 1.356 against 1.246.
  CHECK(bolted_f > without_f + 0.02);
}
