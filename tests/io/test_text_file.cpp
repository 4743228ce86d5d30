// Whole text files written through a temporary file and a rename (io/text_file.hpp).
#include <catch2/catch.hpp>
#include <filesystem>
#include <stdexcept>

#include "io/text_file.hpp"
#include "support/cli_helpers.hpp"

namespace fs = std::filesystem;

TEST_CASE("a text file is replaced whole, and a failure names the file", "[io]") {
  const dda::test::TempDir dir("dda-text-file-");
  const fs::path path = dir.path / "report.json";
  dda::write_text_file(path.string(), "first\n");
  dda::write_text_file(path.string(), "second, longer\n");
  CHECK(dda::test::read_file(path) == "second, longer\n");
  CHECK_FALSE(fs::exists(dir.path / "report.json.tmp"));  // nothing left beside it
  // A directory that does not exist: an error naming the temporary file's path.
  const fs::path missing = dir.path / "no-such-dir" / "report.json";
  CHECK_THROWS_WITH(dda::write_text_file(missing.string(), "x"),
                    Catch::Contains((missing.string() + ".tmp")));
  CHECK_FALSE(fs::exists(missing));
}
