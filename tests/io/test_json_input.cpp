// The input readers' shared pieces (io/json_input.hpp): text echoed in messages cut to a
// readable length, and input files refused before reading when they are not regular files
// or are too large.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "io/json_input.hpp"
#include "support/cli_helpers.hpp"

namespace fs = std::filesystem;
using namespace dda::input;

TEST_CASE("shown_text and quoted_text cut long text to 80 characters, never inside one",
          "[input]") {
  CHECK(shown_text("rock") == "rock");
  CHECK(shown_text(std::string(80, 'a')) == std::string(80, 'a'));
  CHECK(shown_text(std::string(81, 'a')) == std::string(80, 'a') + "... (81 characters)");
  CHECK(quoted_text("my rock") == "\"my rock\"");
  CHECK(quoted_text(std::string(100000, 'k')) ==
        "\"" + std::string(80, 'k') + "...\" (100000 characters)");
  // Characters, not bytes: 100 two-byte characters are 100, cut after the 80th whole one.
  std::string accents;
  for (int i = 0; i < 100; ++i) accents += "\xC3\xA9";
  CHECK(shown_text(accents) == accents.substr(0, 160) + "... (100 characters)");
  const std::string first80 = accents.substr(0, 160);
  CHECK(quoted_text(first80) == "\"" + first80 + "\"");
  // A two-byte character straddling byte 80 stays whole.
  const std::string straddling = std::string(79, 'a') + "\xC3\xA9" + "bb";
  CHECK(quoted_text(straddling) == "\"" + std::string(79, 'a') + "\xC3\xA9...\" (82 characters)");
  // Escapes, and bytes that are not UTF-8 (a line of a CSV record) do not stop the message.
  CHECK(quoted_text("a\"b\n") == "\"a\\\"b\\n\"");
  CHECK_NOTHROW(quoted_text("\xFF\xFE"));
}

TEST_CASE("quoted_name_list shows at most 20 names, each cut", "[input]") {
  CHECK(quoted_name_list({"clay", "rock"}) == "\"clay\", \"rock\"");
  std::vector<std::string> many;
  for (int i = 0; i < 25; ++i) many.push_back(std::string("m") + std::to_string(i));
  const std::string list = quoted_name_list(many);
  CHECK(list.find("\"m19\" and 5 more") != std::string::npos);
  CHECK(list.find("m20") == std::string::npos);
  CHECK(quoted_name_list({std::string(1000, 'r')}) ==
        "\"" + std::string(80, 'r') + "...\" (1000 characters)");
}

TEST_CASE("member_path quotes and cuts a long key, plain or not", "[input]") {
  CHECK(member_path("control", "time_step") == "control.time_step");
  CHECK(member_path("materials", "my rock") == "materials[\"my rock\"]");
  CHECK(member_path("", std::string(100000, 'k')) ==
        "[\"" + std::string(80, 'k') + "...\" (100000 characters)]");
  CHECK(member_path("materials", std::string(81, 'k')) ==
        "materials[\"" + std::string(80, 'k') + "...\" (81 characters)]");
}

TEST_CASE("read_input_file refuses what is not a regular file, or is too large, before reading",
          "[input]") {
  dda::test::TempDir dir("dda-json-input-");
  CHECK_THROWS_WITH(read_input_file("/dev/zero", "a scene file"),
                    "/dev/zero: not read: it is a character device, not a regular file; a scene "
                    "file must be a regular file (save the input to one first)");
  const fs::path fifo = dir.path / "pipe";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(read_input_file(fifo.string(), "a model file"),
                    Catch::StartsWith(fifo.string() + ": not read: it is a pipe (FIFO)"));
  CHECK_THROWS_WITH(read_input_file(dir.path.string(), "a model file"),
                    dir.path.string() + ": cannot open: it is a directory, not a model file");
  CHECK_THROWS_WITH(read_input_file((dir.path / "missing").string(), "a model file"),
                    Catch::StartsWith((dir.path / "missing").string() + ": cannot open file (") &&
                        Catch::Contains("No such file"));
  // At the limit: read; one byte more: refused without reading (a sparse file).
  const fs::path big = dir.path / "big";
  dda::test::write_file(big, "x");
  fs::resize_file(big, kLargestInputBytes);
  CHECK(read_input_file(big.string(), "a scene file").size() == kLargestInputBytes);
  fs::resize_file(big, kLargestInputBytes + 1);
  CHECK_THROWS_WITH(read_input_file(big.string(), "a scene file"),
                    Catch::StartsWith(big.string() + ": not read: the file is 67108865 bytes, "
                                                     "larger than the 64 MiB"));
  // A link to a regular file is read.
  const fs::path small = dir.path / "small.json", link = dir.path / "link.json";
  dda::test::write_file(small, "{}");
  fs::create_symlink(small, link);
  CHECK(read_input_file(link.string(), "a scene file") == "{}");
}
