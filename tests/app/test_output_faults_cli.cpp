// Output faults through the real command line (the input half is test_hostile_inputs_cli.cpp):
// an output path that holds a device, a FIFO or a directory is never replaced; a full disk
// (/dev/full) or a file-size limit (ulimit -f, whose SIGXFSZ dda ignores) is "results could not
// be written", exit 1 naming the file, with no file cut short under its final name and no
// temporary file left; dda fos checks its output directory before any work.
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/cli_helpers.hpp"

namespace fs = std::filesystem;
using dda::test::CommandResult;
using dda::test::contains;
using dda::test::shell_quote;

namespace {

const std::string kExe = shell_quote(DDA_EXE);
const std::string kModel = shell_quote(std::string(DDA_SOURCE_DIR) + "/models/small-slope.json");

CommandResult dda_with(const std::string& args) { return dda::test::run_command(kExe + " " + args); }

// dda under a file-size limit of `blocks` (sh's ulimit -f: 512-byte blocks in dash, 1024 in
// bash; the cases below hold for either).
CommandResult dda_limited(int blocks, const std::string& args) {
  return dda::test::run_command(
      "sh -c " + shell_quote("ulimit -f " + std::to_string(blocks) + "; exec " + kExe + " " + args));
}

// Every file under `dir` (recursively) whose name ends in ".tmp", or that starts with
// ".dda-probe" (none may be left behind).
std::vector<std::string> leftovers(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.ends_with(".tmp") || name.starts_with(".dda-probe")) found.push_back(e.path().string());
  }
  return found;
}

bool is_char_device(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

// A scene of a block sliding for `end_time` s on a fixed floor, output every step.
std::string sliding_scene(double end_time) {
  return R"json({
    "control": {"time_step": 0.001, "end_time": )json" + std::to_string(end_time) + R"json(, "output_every": 1},
    "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
    "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
    "gravity": [0, -9.81],
    "monitors": [{"name": "top", "point": [0.5, 1.0]}],
    "blocks": [{"vertices": [[-5, -1], [5, -1], [5, 0], [-5, 0]], "material": "rock", "fixed": true},
               {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "rock",
                "velocity": [1, 0, 0]}]})json";
}

// An elastic point strained in 200 000 increments (some 20 MB of CSV rows), written to
// DIR/spec.json: output far larger than a file-size limit or a pipe holds.
fs::path long_elastic_spec(const fs::path& dir) {
  const fs::path spec = dir / "spec.json";
  dda::test::write_file(spec, R"json({
    "material": {"model": "elastic", "density": 2000, "young": 5e7, "poisson": 0.3},
    "path": [{"steps": 200000, "strain": {"exx": 0.01}}]})json");
  return spec;
}

// Every line of `path` has `commas` commas, and the file ends with a line end.
void check_whole_rows(const fs::path& path, long commas) {
  const std::string text = dda::test::read_file(path);
  REQUIRE_FALSE(text.empty());
  CHECK(text.back() == '\n');
  const std::vector<std::string> lines = dda::test::read_lines(path);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    INFO(path.string() << " line " << k + 1 << ": " << lines[k]);
    REQUIRE(std::count(lines[k].begin(), lines[k].end(), ',') == commas);
  }
}

}  // namespace

TEST_CASE("dda cut never replaces a device node, a link to one or a directory", "[cli][output]") {
  const dda::test::TempDir dir("dda-out-faults-cut-");
  // A link to /dev/full: the scene goes into the device (which is full), nothing replaces
  // the link and no picture is written beside it.
  const fs::path full = dir.path / "full";
  fs::create_symlink("/dev/full", full);
  const CommandResult r = dda_with("cut " + kModel + " --out " + shell_quote(full.string()));
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "dda: error: output: cannot write " + full.string() +
                               " (No space left on device)"));
  CHECK(fs::is_symlink(full));
  CHECK(fs::read_symlink(full) == "/dev/full");
  CHECK(is_char_device("/dev/full"));
  CHECK_FALSE(fs::exists(dir.path / "full.png"));
  CHECK(leftovers(dir.path).empty());

  // A device node of our own (root only: mknod), the same as /dev/full: left a device.
  if (::geteuid() == 0) {
    const fs::path node = dir.path / "node";
    REQUIRE(::mknod(node.c_str(), S_IFCHR | 0644, makedev(1, 7)) == 0);
    const CommandResult n = dda_with("cut " + kModel + " --out " + shell_quote(node.string()));
    INFO(n.output);
    CHECK(n.exit_code == 1);
    CHECK(contains(n.output, "cannot write " + node.string() + " (No space left on device)"));
    CHECK(is_char_device(node));
    CHECK_FALSE(fs::exists(dir.path / "node.png"));
  }

  // /dev/null takes the scene (written into, not replaced), and there is no picture.
  const fs::path null = dir.path / "null";
  fs::create_symlink("/dev/null", null);
  const CommandResult z = dda_with("cut " + kModel + " --out " + shell_quote(null.string()));
  INFO(z.output);
  CHECK(z.exit_code == 0);
  CHECK(contains(z.output, "no picture of the blocks"));
  CHECK(fs::is_symlink(null));
  CHECK_FALSE(fs::exists(dir.path / "null.png"));

  // A directory under the scene's name: refused before the cut, left as it was.
  const fs::path sub = dir.path / "scene.json";
  fs::create_directories(sub / "inside");
  const CommandResult d = dda_with("cut " + kModel + " --out " + shell_quote(sub.string()));
  INFO(d.output);
  CHECK(d.exit_code == 1);
  CHECK(contains(d.output, "dda: error: output: " + sub.string() + " is a directory"));
  CHECK_FALSE(contains(d.output, "blocks; scene in"));  // before the cut
  CHECK(fs::is_directory(sub / "inside"));
  CHECK_FALSE(fs::exists(dir.path / "scene.png"));
  CHECK(leftovers(dir.path).empty());
}

TEST_CASE("dda run and material-point never replace a device node or a FIFO", "[cli][output]") {
  const dda::test::TempDir dir("dda-out-faults-run-");
  const fs::path scene = dir.path / "scene.json";
  dda::test::write_file(scene, sliding_scene(0.01));
  // --out a link to a device: no directory can be made there, nothing is written.
  const fs::path full = dir.path / "full";
  fs::create_symlink("/dev/full", full);
  const CommandResult r = dda_with("run " + shell_quote(scene.string()) + " --out " + shell_quote(full.string()));
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "dda: error: output: cannot create directory"));
  CHECK(fs::is_symlink(full));
  CHECK(is_char_device("/dev/full"));

  // A FIFO where history.csv goes: the run stops before it removes or writes anything.
  const fs::path out = dir.path / "out";
  fs::create_directories(out);
  REQUIRE(::mkfifo((out / "history.csv").c_str(), 0644) == 0);
  dda::test::write_file(out / "summary.json", "an earlier run's\n");
  const CommandResult f = dda_with("run " + shell_quote(scene.string()) + " --out " + shell_quote(out.string()));
  INFO(f.output);
  CHECK(f.exit_code == 1);
  CHECK(contains(f.output, "not a regular file; dda does not replace it: " + (out / "history.csv").string()));
  CHECK(fs::is_fifo(out / "history.csv"));
  CHECK(dda::test::read_file(out / "summary.json") == "an earlier run's\n");  // nothing removed
  CHECK_FALSE(fs::exists(out / "vtk"));

  // material-point into /dev/full (through a link): the header cannot be written, exit 1,
  // the link and the device stay.
  const fs::path spec = dir.path / "spec.json";
  dda::test::write_file(spec, R"json({
    "material": {"model": "elastic", "density": 2000, "young": 5e7, "poisson": 0.3},
    "path": [{"steps": 10, "strain": {"exx": 0.01}}]})json");
  const CommandResult m = dda_with("material-point " + shell_quote(spec.string()) + " --out " +
                                   shell_quote(full.string()));
  INFO(m.output);
  CHECK(m.exit_code == 1);
  CHECK(contains(m.output, "dda: error: output: cannot write " + full.string() +
                               " (No space left on device)"));
  CHECK(fs::is_symlink(full));
  CHECK(is_char_device("/dev/full"));
  // ... and into a directory: refused, the directory left as it was.
  fs::create_directories(dir.path / "csv.csv" / "inside");
  const CommandResult md = dda_with("material-point " + shell_quote(spec.string()) + " --out " +
                                    shell_quote((dir.path / "csv.csv").string()));
  INFO(md.output);
  CHECK(md.exit_code == 1);
  CHECK(contains(md.output, (dir.path / "csv.csv").string() + " is a directory"));
  CHECK(fs::is_directory(dir.path / "csv.csv" / "inside"));
  CHECK(leftovers(dir.path).empty());
}

TEST_CASE("dda run under a file-size limit stops with exit 1 and whole rows and files",
          "[cli][output]") {
  const dda::test::TempDir dir("dda-out-faults-limit-");
  const fs::path scene = dir.path / "scene.json";
  dda::test::write_file(scene, sliding_scene(1.0));
  const fs::path out = dir.path / "out";
  // 20 blocks of 512 or 1024 bytes: history.csv (two rows of ~450 bytes a step) passes it
  // after some tens of steps, long before the run's 1000; a VTK frame stays below it.
  const CommandResult r = dda_limited(20, "run " + shell_quote(scene.string()) + " --out " +
                                              shell_quote(out.string()));
  INFO(r.output);
  CHECK(r.exit_code == 1);  // not 153 (killed by SIGXFSZ)
  CHECK(contains(r.output, "dda: error: output: cannot write " + (out / "history.csv").string() +
                               " (File too large"));
  CHECK(contains(r.output, "cut back to the end of its last whole row"));
  check_whole_rows(out / "history.csv", 25);
  check_whole_rows(out / "monitors.csv", 8);
  // Whole steps: two rows (two blocks) of each step after the header.
  const std::vector<std::string> rows = dda::test::read_lines(out / "history.csv");
  CHECK(rows.size() % 2 == 1);
  CHECK(rows.size() > 10);
  // Every frame the index lists is there and complete, and no temporary file is left.
  const std::string pvd = dda::test::read_file(out / "blocks.pvd");
  CHECK(contains(pvd, "</VTKFile>"));
  for (const auto& e : fs::directory_iterator(out / "vtk")) {
    INFO(e.path());
    CHECK(dda::test::read_file(e.path()).ends_with("</VTKFile>\n"));
  }
  CHECK(leftovers(dir.path).empty());
  CHECK_FALSE(fs::exists(out / "summary.json"));
}

TEST_CASE("dda cut and material-point under a file-size limit leave no part of a file",
          "[cli][output]") {
  const dda::test::TempDir dir("dda-out-faults-limit-");
  // The scene (10 kB) passes 2 blocks: nothing is written, no temporary file is left.
  const fs::path scene = dir.path / "s.json";
  const CommandResult small = dda_limited(2, "cut " + kModel + " --out " + shell_quote(scene.string()));
  INFO(small.output);
  CHECK(small.exit_code == 1);
  CHECK(contains(small.output, "dda: error: output: cannot write " + scene.string() + " (File too large"));
  CHECK_FALSE(fs::exists(scene));
  CHECK(leftovers(dir.path).empty());
  // 26 blocks (13.3 kB in dash's 512-byte units, 26.6 kB in bash's 1024) hold the scene
  // (12.4 kB) but not the picture (29.5 kB, deflated): the scene is written whole, the
  // picture not at all.
  const CommandResult big = dda_limited(26, "cut " + kModel + " --out " + shell_quote(scene.string()));
  INFO(big.output);
  CHECK(big.exit_code == 1);
  CHECK(contains(big.output, "dda: error: output: cannot write " + (dir.path / "s.png").string() +
                                 " (File too large"));
  CHECK(nlohmann::json::parse(dda::test::read_file(scene)).contains("blocks"));
  CHECK_FALSE(fs::exists(dir.path / "s.png"));
  CHECK(leftovers(dir.path).empty());

  // material-point: rows go out 4096 at a time; the limit falls inside a batch, and the
  // file is cut back to the last whole batch.
  const fs::path spec = long_elastic_spec(dir.path);
  const fs::path csv = dir.path / "point.csv";
  const CommandResult m = dda_limited(2000, "material-point " + shell_quote(spec.string()) +
                                                " --out " + shell_quote(csv.string()));
  INFO(m.output);
  CHECK(m.exit_code == 1);
  CHECK(contains(m.output, "dda: error: output: cannot write " + csv.string() + " (File too large"));
  check_whole_rows(csv, 9);
  const std::vector<std::string> lines = dda::test::read_lines(csv);
  CHECK(lines.size() > 4096);
  // The header and step 0 (written at once, step 0 being a multiple of 4096), then whole
  // batches of 4096 increments.
  CHECK((lines.size() - 2) % 4096 == 0);
  CHECK(leftovers(dir.path).empty());
}

TEST_CASE("dda fos checks its output directory before any work, and writes its report whole",
          "[cli][output][fos]") {
  const dda::test::TempDir dir("dda-out-faults-fos-");
  const fs::path scene = dir.path / "scene.json";
  dda::test::write_file(scene, sliding_scene(0.2));
  // Under a regular file no directory can be made: exit 1 before the consolidation.
  dda::test::write_file(dir.path / "file", "mine\n");
  const fs::path under = dir.path / "file" / "out";
  const CommandResult r = dda_with("fos " + shell_quote(scene.string()) + " --out " + shell_quote(under.string()));
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "dda: error: output: cannot create directory " + under.string()));
  CHECK_FALSE(contains(r.output, "consolidating"));
  CHECK(dda::test::read_file(dir.path / "file") == "mine\n");
  // A directory where report.json goes: refused before the consolidation.
  const fs::path out = dir.path / "out";
  fs::create_directories(out / "report.json");
  const CommandResult d = dda_with("fos " + shell_quote(scene.string()) + " --out " + shell_quote(out.string()));
  INFO(d.output);
  CHECK(d.exit_code == 1);
  CHECK(contains(d.output, (out / "report.json").string() + " is a directory"));
  CHECK_FALSE(contains(d.output, "consolidating"));
  CHECK(fs::is_directory(out / "report.json"));
  CHECK(leftovers(dir.path).empty());
  // A file-size limit of 1 block lets the probe through but not the report: exit 1 (not
  // 153), no report.json cut short, no temporary file left.
  const fs::path limited = dir.path / "limited";
  const CommandResult l = dda_limited(1, "fos " + shell_quote(scene.string()) +
                                             " --method limit-analysis --out " + shell_quote(limited.string()));
  INFO(l.output);
  CHECK(l.exit_code == 1);
  CHECK(contains(l.output, "consolidating"));
  CHECK(contains(l.output, "dda: error: output: cannot write " + (limited / "report.json").string() +
                               " (File too large"));
  CHECK_FALSE(fs::exists(limited / "report.json"));
  CHECK(leftovers(dir.path).empty());
}

TEST_CASE("a dangling link at an output path stays a link, and a FIFO whose reader leaves is exit 1",
          "[cli][output]") {
  const dda::test::TempDir dir("dda-out-faults-links-");
  // dda cut --out a link that names no file yet: the scene is written where the link points
  // and the link stays (it was replaced by a regular file, the link lost).
  const fs::path link = dir.path / "scene.json";
  fs::create_symlink("made-later.json", link);
  const CommandResult c = dda_with("cut " + kModel + " --out " + shell_quote(link.string()));
  INFO(c.output);
  CHECK(c.exit_code == 0);
  CHECK(fs::is_symlink(link));
  CHECK(fs::is_regular_file(dir.path / "made-later.json"));
  CHECK(contains(dda::test::read_file(dir.path / "made-later.json"), "\"blocks\""));
  CHECK(leftovers(dir.path).empty());

  // dda material-point into a FIFO whose reader takes 10 bytes and leaves: the next write
  // fails with EPIPE, reported as a file it cannot write (exit 1), not SIGPIPE (exit 141,
  // nothing said). 200 000 increments write some 20 MB, far more than a pipe holds.
  const fs::path spec = long_elastic_spec(dir.path);
  const fs::path fifo = dir.path / "rows.csv";
  REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  const CommandResult m = dda::test::run_command(
      "sh -c " + shell_quote("head -c 10 " + shell_quote(fifo.string()) + " >/dev/null & exec " + kExe +
                             " material-point " + shell_quote(spec.string()) + " --out " +
                             shell_quote(fifo.string())));
  INFO(m.output);
  CHECK(m.exit_code == 1);
  CHECK(contains(m.output, "dda: error: output: cannot write " + fifo.string() + " (Broken pipe)"));
  CHECK(fs::is_fifo(fifo));
}
