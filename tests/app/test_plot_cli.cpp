// dda run's pictures and dda plot through the real executable: the default run leaves its
// pictures in DIR/plot, each a PNG of the stated width, small, with the blocks' colours on
// it; --no-picture leaves none; dda plot redraws them with other options; bad options and a
// directory that is not a run's are input errors (exit 2) naming what is wrong.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "io/colour_maps.hpp"
#include "support/cli_helpers.hpp"
#include "support/picture_checks.hpp"

namespace fs = std::filesystem;
using dda::test::run_command;
using dda::test::shell_quote;
namespace pic = dda::test::picture;

namespace {

std::string dda_exe() { return shell_quote(DDA_EXE); }

}  // namespace

TEST_CASE("plot cli: the default run draws its pictures, dda plot redraws them", "[plot][cli]") {
  dda::test::TempDir dir("dda_test_plot_cli_");
  const fs::path out = dir.path / "out";
  const auto run = run_command(dda_exe() + " run --out " + shell_quote(out.string()));
  REQUIRE(run.exit_code == 0);
  CHECK(dda::test::contains(run.output, "dda: pictures:"));
  // The default scene has contacts and no monitors: blocks, joint states, force chains, energy.
  for (const char* name : {"blocks.png", "joint_states.png", "force_chains.png", "energy.png"}) {
    const fs::path p = out / "plot" / name;
    REQUIRE(fs::exists(p));
    const pic::Bytes bytes = pic::read_file(p);
    // Flat colours deflate to a few tens of kB (measured 12-17 kB); 200 kB is far above any
    // picture of this scene and far below what stored pixels took (about 4 MB).
    CHECK(bytes.size() < 200000U);
    const pic::Decoded d = pic::decode_png(bytes);
    CHECK(d.width == (std::string(name) == "energy.png" ? 1000U : 1600U));
  }
  CHECK_FALSE(fs::exists(out / "plot" / "monitors.png"));

  // The blocks picture shows the fixed floor's grey and the moving blocks' viridis colours:
  // the octagon moved most (yellow, the bar's top).
  const pic::Decoded blocks = pic::decode_png(pic::read_file(out / "plot" / "blocks.png"));
  int grey = 0, yellow = 0;
  for (std::size_t i = 0; i < blocks.pixels.size(); i += 3) {
    const dda::Rgb c{blocks.pixels[i], blocks.pixels[i + 1], blocks.pixels[i + 2]};
    grey += c == dda::Rgb{190, 190, 190};
    yellow += c == dda::sequential_colour(1.0);
  }
  CHECK(grey > 10000);   // the floor, 10 x 1 m at about 140 px/m
  CHECK(yellow > 5000);  // the octagon, 0.71 m^2

  const auto plot = run_command(dda_exe() + " plot " + shell_quote(out.string()) + " --field velocity --time 1.0 --out " +
                                shell_quote((dir.path / "p2").string()));
  CHECK(plot.exit_code == 0);
  CHECK(fs::exists(dir.path / "p2" / "blocks.png"));
  // Two times: each frame's pictures named after its time, the single-time names gone.
  const auto two = run_command(dda_exe() + " plot " + shell_quote(out.string()) + " --time 0.5 --time 2.5 --out " +
                               shell_quote((dir.path / "p2").string()));
  CHECK(two.exit_code == 0);
  int at_times = 0;
  for (const auto& e : fs::directory_iterator(dir.path / "p2")) at_times += e.path().filename().string().rfind("blocks_t", 0) == 0;
  CHECK(at_times == 2);
  CHECK_FALSE(fs::exists(dir.path / "p2" / "blocks.png"));

  const fs::path quiet = dir.path / "quiet";
  REQUIRE(run_command(dda_exe() + " run --no-picture --out " + shell_quote(quiet.string())).exit_code == 0);
  CHECK_FALSE(fs::exists(quiet / "plot"));
}

TEST_CASE("plot cli: bad options and a directory that is not a run's are input errors", "[plot][cli]") {
  dda::test::TempDir dir("dda_test_plot_cli_bad_");
  const fs::path out = dir.path / "out";
  REQUIRE(run_command(dda_exe() + " run --no-picture --out " + shell_quote(out.string())).exit_code == 0);
  const auto field = run_command(dda_exe() + " plot " + shell_quote(out.string()) + " --field strain");
  CHECK(field.exit_code == 2);
  CHECK(dda::test::contains(field.output, "unknown field \"strain\""));
  const auto early = run_command(dda_exe() + " plot " + shell_quote(out.string()) + " --time -1");
  CHECK(early.exit_code == 2);
  CHECK(dda::test::contains(early.output, "before the first frame"));
  const auto plastic = run_command(dda_exe() + " plot " + shell_quote(out.string()) + " --field plastic-strain");
  CHECK(plastic.exit_code == 0);  // this version's frames carry plastic_strain (0 for elastic blocks)
  const auto not_run = run_command(dda_exe() + " plot " + shell_quote(dir.path.string()));
  CHECK(not_run.exit_code == 2);
  CHECK(dda::test::contains(not_run.output, "holds no blocks.pvd"));
  const auto missing = run_command(dda_exe() + " plot " + shell_quote((dir.path / "none").string()));
  CHECK(missing.exit_code == 2);
  CHECK(dda::test::contains(missing.output, "is not a directory"));
}
