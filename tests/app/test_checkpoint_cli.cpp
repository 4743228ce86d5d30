// dda run --checkpoint-every and --restart through the real command line: a run continued
// from its checkpoint leaves the output directory the run in one piece leaves, byte for
// byte (but the wall time), whether it was split at a checkpoint or stopped by a signal.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/checkpoint_scene.hpp"
#include "support/cli_helpers.hpp"
#include "support/plane_block_scene.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using dda::test::shell_quote;

dda::test::CommandResult dda_run(const std::string& args) {
  return dda::test::run_command(shell_quote(DDA_EXE) + " run " + args + " --no-picture");
}

// The summary without its clock.
json summary_of(const fs::path& dir) {
  json s = json::parse(dda::test::read_file(dir / "summary.json"));
  s.erase("wall_time_s");
  return s;
}

std::vector<std::string> frames_of(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir / "vtk")) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Every file of the run's output the same, byte for byte (summary.json but its wall time).
void require_same_output(const fs::path& a, const fs::path& b) {
  for (const char* name : {"history.csv", "monitors.csv", "bolts.csv", "blocks.pvd", "contacts.pvd",
                           "bolts.pvd"}) {
    INFO(name);
    CHECK(dda::test::read_file(a / name) == dda::test::read_file(b / name));
  }
  CHECK(summary_of(a) == summary_of(b));
  const std::vector<std::string> frames = frames_of(a);
  REQUIRE(frames == frames_of(b));
  for (const std::string& f : frames) {
    INFO(f);
    CHECK(dda::test::read_file(a / "vtk" / f) == dda::test::read_file(b / "vtk" / f));
  }
}

}  // namespace

TEST_CASE("dda run split at a checkpoint and restarted leaves what the run in one piece leaves",
          "[cli][checkpoint]") {
  // Both solver paths: a factorisation every solve, and the default kept factor (whose
  // state the checkpoint carries, so that the continuation is exact on it too).
  const std::string solver = GENERATE(as<std::string>{}, "factorise", "reuse");
  INFO("linear_solver " << solver);
  dda::test::TempDir dir("dda-checkpoint-");
  const fs::path scene = dir.path / "scene.json";
  dda::test::write_file(scene, dda::test::checkpoint_scene("0.08", solver));
  const fs::path whole = dir.path / "whole";
  REQUIRE(dda_run(shell_quote(scene.string()) + " --out " + shell_quote(whole.string())).exit_code == 0);
  // 26 steps; checkpoints every 7 leave step 21's (the first stage ends at step 10).
  const fs::path split = dir.path / "split";
  const auto first = dda_run(shell_quote(scene.string()) + " --out " + shell_quote(split.string()) +
                             " --checkpoint-every 7");
  REQUIRE(first.exit_code == 0);
  const fs::path checkpoint = split / "checkpoint.ddack";
  REQUIRE(fs::exists(checkpoint));
  // Restarted into a new directory: the continuation alone, steps 22 to 26.
  const fs::path fresh = dir.path / "fresh";
  const auto r = dda_run("--restart " + shell_quote(checkpoint.string()) + " --out " +
                         shell_quote(fresh.string()));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::vector<std::string> all = dda::test::read_lines(whole / "history.csv");
  std::vector<std::string> after{all.front()};
  for (const std::string& line : all) {
    if (std::isdigit(static_cast<unsigned char>(line[0])) && std::stoi(line) > 21) after.push_back(line);
  }
  CHECK(after.size() == 1 + 5 * 2);  // steps 24 and 26 recorded (output every 3, and the end)
  CHECK(dda::test::read_lines(fresh / "history.csv") == after);
  CHECK(summary_of(fresh) == summary_of(whole));
  // Restarted into its own directory (no --out: the checkpoint's), which holds rows and
  // frames up to step 26: cut back to step 21 and continued, it is the run in one piece.
  REQUIRE(dda_run("--restart " + shell_quote(checkpoint.string())).exit_code == 0);
  require_same_output(whole, split);
}

TEST_CASE("dda run stopped by a signal leaves a checkpoint that continues it exactly",
          "[cli][checkpoint]") {
  const std::string solver = GENERATE(as<std::string>{}, "factorise", "reuse");
  INFO("linear_solver " << solver);
  dda::test::TempDir dir("dda-checkpoint-signal-");
  const fs::path scene = dir.path / "scene.json";
  // 10 static steps and 1200 dynamic ones: long enough to be stopped on the way.
  dda::test::write_file(scene, dda::test::checkpoint_scene("6.0", solver));
  const fs::path whole = dir.path / "whole";
  REQUIRE(dda_run(shell_quote(scene.string()) + " --out " + shell_quote(whole.string())).exit_code == 0);
  const fs::path out = dir.path / "out";
  const fs::path history = out / "history.csv";
  // Waits for more than 300 lines (60 recorded steps of 5 blocks: step 177 on), then SIGINT.
  const std::string f = shell_quote(history.string());
  std::string command = "(";
  command += shell_quote(DDA_EXE);
  command += " run " + shell_quote(scene.string()) + " --out " + shell_quote(out.string());
  command += " --no-picture & pid=$!; n=0; while [ $n -lt 1200 ] && [ \"$(cat " + f;
  command += " 2>/dev/null | wc -l)\" -le 300 ]; do sleep 0.05; n=$((n+1)); done; ";
  command += "kill -INT $pid; wait $pid; echo rc=$?)";
  const auto r = dda::test::run_command(command);
  INFO(r.output);
  REQUIRE(dda::test::contains(r.output, "rc=130"));
  REQUIRE(dda::test::contains(r.output, "continue with dda run --restart"));
  const json stopped = json::parse(dda::test::read_file(out / "summary.json"));
  REQUIRE(stopped["interrupted"] == true);
  const int steps = stopped["steps"];
  CHECK(steps < 1210);
  const auto again = dda_run("--restart " + shell_quote((out / "checkpoint.ddack").string()) +
                             " --out " + shell_quote(out.string()));
  INFO(again.output);
  REQUIRE(again.exit_code == 0);
  require_same_output(whole, out);
}

TEST_CASE("dda run --restart refuses what it cannot continue, naming it", "[cli][checkpoint]") {
  dda::test::TempDir dir("dda-checkpoint-bad-");
  const fs::path scene = dir.path / "scene.json";
  dda::test::write_file(scene, dda::test::checkpoint_scene());
  const fs::path out = dir.path / "out";
  REQUIRE(dda_run(shell_quote(scene.string()) + " --out " + shell_quote(out.string()) +
                  " --checkpoint-every 5").exit_code == 0);
  const fs::path checkpoint = out / "checkpoint.ddack";
  const std::string bytes = dda::test::read_file(checkpoint);

  const fs::path garbage = dir.path / "garbage.ddack";
  dda::test::write_file(garbage, "{\"not\": \"a checkpoint\"}");
  auto r = dda_run("--restart " + shell_quote(garbage.string()) + " --out " + shell_quote((dir.path / "o1").string()));
  CHECK(r.exit_code == 2);
  CHECK(dda::test::contains(r.output, garbage.string() + ": not a checkpoint dda can read"));

  const fs::path cut = dir.path / "cut.ddack";
  dda::test::write_file(cut, bytes.substr(0, bytes.size() - 100));
  r = dda_run("--restart " + shell_quote(cut.string()) + " --out " + shell_quote((dir.path / "o2").string()));
  CHECK(r.exit_code == 2);
  CHECK(dda::test::contains(r.output, cut.string() + ": not a checkpoint dda can read (its length"));

  r = dda_run("--restart " + shell_quote((dir.path / "missing.ddack").string()));
  CHECK(r.exit_code == 2);
  CHECK(dda::test::contains(r.output, "missing.ddack"));

  r = dda_run(shell_quote(scene.string()) + " --restart " + shell_quote(checkpoint.string()));
  CHECK(r.exit_code == 2);
  CHECK(dda::test::contains(r.output, "give no scene file with it"));

  // A directory holding another run's history: not continued into.
  const fs::path other = dir.path / "other";
  const fs::path other_scene = dir.path / "other.json";
  dda::test::write_file(other_scene, R"json({
    "control": {"time_step": 0.01, "steps": 3},
    "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
    "blocks": [{"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock"}]})json");
  REQUIRE(dda_run(shell_quote(other_scene.string()) + " --out " + shell_quote(other.string())).exit_code == 0);
  r = dda_run("--restart " + shell_quote(checkpoint.string()) + " --out " + shell_quote(other.string()));
  CHECK(r.exit_code == 2);
  CHECK(dda::test::contains(r.output, (other / "history.csv").string() + ": not the file of the run"));
}

TEST_CASE("dda fos from an earlier run's consolidation finds the same factor and refuses another "
          "scene's",
          "[cli][checkpoint][fos]") {
  dda::test::TempDir dir("dda-checkpoint-fos-");
  const fs::path scene = dir.path / "plane.json";
  dda::test::write_file(scene, dda::test::plane_block_scene(30.0, 32.0).dump());
  const auto fos = [&](const fs::path& s, const fs::path& out, const std::string& options) {
    return dda::test::run_command(shell_quote(DDA_EXE) + " fos " + shell_quote(s.string()) +
                                  " --out " + shell_quote(out.string()) +
                                  " --skip-limit-analysis " + options);
  };
  const fs::path a = dir.path / "a";
  auto r = fos(scene, a, "");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const fs::path consolidated = a / "consolidated.ddack";
  REQUIRE(fs::exists(consolidated));
  const fs::path b = dir.path / "b";
  r = fos(scene, b, "--consolidated " + shell_quote(consolidated.string()));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::string says = "the consolidation of ";
  says += scene.string();
  says += " from";
  CHECK(dda::test::contains(r.output, says));
  // The reports without their clocks.
  const auto report = [](const fs::path& dir) {
    json r = json::parse(dda::test::read_file(dir / "report.json"));
    for (json& t : r["trials"]) t.erase("wall_time_s");
    return r;
  };
  const json ra = report(a);
  const json rb = report(b);
  // The factor as written (the shortest text that reads back as the same double): equal
  // texts are equal doubles, bit for bit. The plane's closed form is tan 32 / tan 30 = 1.082.
  REQUIRE(ra["factor_of_safety"].is_number());
  CHECK(ra["factor_of_safety"].dump() == rb["factor_of_safety"].dump());
  CHECK(std::abs(ra["factor_of_safety"].get<double>() - 1.0823) < 0.05);
  CHECK(ra["trials"] == rb["trials"]);
  CHECK(ra["consolidation"]["steps"] == rb["consolidation"]["steps"]);
  CHECK(ra["consolidation"]["settling"] == rb["consolidation"]["settling"]);

  // The same file for a scene that differs (friction 33 degrees), or at another
  // consolidation factor: refused, naming the file.
  const fs::path other = dir.path / "other.json";
  dda::test::write_file(other, dda::test::plane_block_scene(30.0, 33.0).dump());
  r = fos(other, dir.path / "c", "--consolidated " + shell_quote(consolidated.string()));
  CHECK(r.exit_code == 2);
  CHECK(dda::test::contains(r.output, consolidated.string() + ": the consolidation of another scene"));
  r = fos(scene, dir.path / "d",
          "--consolidation-factor 0.5 --consolidated " + shell_quote(consolidated.string()));
  CHECK(r.exit_code == 2);
  CHECK(dda::test::contains(r.output, consolidated.string() + ": consolidated at --consolidation-factor"));
  // A run's checkpoint is not a consolidation.
  const fs::path run_scene = dir.path / "run.json";
  dda::test::write_file(run_scene, dda::test::checkpoint_scene());
  const fs::path run_out = dir.path / "run";
  REQUIRE(dda_run(shell_quote(run_scene.string()) + " --out " + shell_quote(run_out.string()) +
                  " --checkpoint-every 5").exit_code == 0);
  r = fos(scene, dir.path / "e", "--consolidated " + shell_quote((run_out / "checkpoint.ddack").string()));
  CHECK(r.exit_code == 2);
  CHECK(dda::test::contains(r.output, "a run checkpoint, not the fos consolidation one asked for"));
}
