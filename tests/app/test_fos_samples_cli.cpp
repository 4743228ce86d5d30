// `dda fos SCENE --samples N --seed S`: the same seed gives the same report whatever the
// number of jobs, the report holds the probabilistic section and the histogram, and a bad
// random_strengths key is refused with its place (exit 2).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/cli_helpers.hpp"
#include "support/plane_block_scene.hpp"

namespace fs = std::filesystem;
using dda::test::run_command;
using dda::test::shell_quote;

namespace {

nlohmann::json run_samples(const fs::path& scene, const fs::path& out, const std::string& options) {
  const dda::test::CommandResult r = run_command(shell_quote(DDA_EXE) + " fos " +
                                                 shell_quote(scene.string()) + " --out " +
                                                 shell_quote(out.string()) + " " + options);
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(std::ifstream(out / "report.json"));
}

}  // namespace

TEST_CASE("dda fos --samples with one seed gives the same samples and estimate twice",
          "[fos][random][cli]") {
  const dda::test::TempDir dir("dda_fos_samples_");
  const fs::path scene = dir.path / "plane.json";
  dda::test::write_file(
      scene, dda::test::with_random_friction(dda::test::plane_block_scene(30.0, 32.0), 32.0, 4.0, 10.0, 54.0)
                 .dump());
  const nlohmann::json a = run_samples(scene, dir.path / "a", "--samples 12 --seed 77 --at-factor 1 --jobs 2");
  const nlohmann::json b = run_samples(scene, dir.path / "b", "--samples 12 --seed 77 --at-factor 1 --jobs 1");
  const nlohmann::json& pa = a.at("probabilistic");
  const nlohmann::json& pb = b.at("probabilistic");
  CHECK(pa.at("mode") == "verdict");
  CHECK(pa.at("seed") == 77);
  CHECK(pa.at("samples_judged") == 12);
  REQUIRE(pa.at("samples").size() == 12);
  for (std::size_t k = 0; k < 12; ++k) {
    CHECK(pa["samples"][k]["values"] == pb["samples"][k]["values"]);
    CHECK(pa["samples"][k]["verdict"] == pb["samples"][k]["verdict"]);
  }
  CHECK(pa.at("probability_of_failure") == pb.at("probability_of_failure"));
  CHECK(pa.at("confidence_interval") == pb.at("confidence_interval"));
  CHECK(fs::exists(dir.path / "a" / "verdicts.png"));
  CHECK(dda::test::contains(dda::test::read_file(dir.path / "a" / "report.md"),
                            "Probabilistic factor of safety"));
  // Another seed draws other values.
  const nlohmann::json c = run_samples(scene, dir.path / "c", "--samples 2 --seed 78 --at-factor 1");
  CHECK(c["probabilistic"]["samples"][0]["values"] != pa["samples"][0]["values"]);

  // The search per sample: a factor each, their statistics and the histogram.
  const nlohmann::json f = run_samples(scene, dir.path / "f", "--samples 2 --seed 77");
  CHECK(f["probabilistic"]["mode"] == "factor");
  CHECK(f["probabilistic"]["factor"]["count"] == 2);
  CHECK(f["probabilistic"]["samples"][0]["values"] == pa["samples"][0]["values"]);
  CHECK(fs::exists(dir.path / "f" / "factors.png"));
}

TEST_CASE("dda fos --samples refuses a bad random_strengths key with its place",
          "[fos][random][cli]") {
  const dda::test::TempDir dir("dda_fos_samples_bad_");
  nlohmann::json scene =
      dda::test::with_random_friction(dda::test::plane_block_scene(30.0, 32.0), 32.0, 4.0, 10.0, 54.0);
  struct Case {
    std::string key;
    nlohmann::json value;
    std::string place;
    std::string words;
  };
  const Case cases[] = {
      {"distribution", "gaussian", "random_strengths.variables[0].distribution", "unknown distribution"},
      {"standard_deviation", -1.0, "random_strengths.variables[0].standard_deviation", "positive"},
      {"joint_material", "bedding", "random_strengths.variables[0].joint_material", "unknown joint material"},
      {"min", -5.0, "random_strengths.variables[0].min", "at least 0"},
  };
  for (const Case& c : cases) {
    nlohmann::json bad = scene;
    bad["random_strengths"]["variables"][0][c.key] = c.value;
    const fs::path path = dir.path / "bad.json";
    dda::test::write_file(path, bad.dump());
    const dda::test::CommandResult r = run_command(shell_quote(DDA_EXE) + " fos " +
                                                   shell_quote(path.string()) + " --out " +
                                                   shell_quote((dir.path / "out").string()) +
                                                   " --samples 3 --seed 1 --at-factor 1");
    INFO(c.key << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(dda::test::contains(r.output, path.string() + ": " + c.place + ": "));
    CHECK(dda::test::contains(r.output, c.words));
  }
  // A normal friction angle reaching below 0 without a min says so.
  nlohmann::json open = scene;
  open["random_strengths"]["variables"][0].erase("min");
  open["random_strengths"]["variables"][0]["mean"] = 5.0;
  const fs::path path = dir.path / "open.json";
  dda::test::write_file(path, open.dump());
  const dda::test::CommandResult r = run_command(shell_quote(DDA_EXE) + " fos " + shell_quote(path.string()) +
                                                 " --out " + shell_quote((dir.path / "out").string()) +
                                                 " --samples 3 --at-factor 1");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(dda::test::contains(r.output, "random_strengths.variables[0]: a normal friction_angle"));
  CHECK(dda::test::contains(r.output, "give \"min\""));
  // --samples on a scene without the key.
  nlohmann::json plain = dda::test::plane_block_scene(30.0, 32.0);
  dda::test::write_file(dir.path / "plain.json", plain.dump());
  const dda::test::CommandResult none = run_command(
      shell_quote(DDA_EXE) + " fos " + shell_quote((dir.path / "plain.json").string()) + " --out " +
      shell_quote((dir.path / "out").string()) + " --samples 3");
  CHECK(none.exit_code == 2);
  CHECK(dda::test::contains(none.output, "random_strengths: --samples"));
}
