// The verification programs' output files appear under their names only when whole
// (verification/common/whole_file.hpp): a writer stopped by an exception leaves neither the
// final name nor its temporary, an earlier file under the name is left as it was, a failed
// write or rename is an error naming the file, and a writer that finishes leaves the whole file.
#include <catch2/catch.hpp>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>

#include "format.hpp"
#include "support/cli_helpers.hpp"
#include "whole_file.hpp"

namespace fs = std::filesystem;

using dda::test::read_file;
using dda::test::TempDir;
using dda::verification::open_csv;
using dda::verification::WholeFile;

TEST_CASE("verification output files: whole under their names or not at all", "[verification]") {
  const TempDir dir("dda_whole_file_");
  const fs::path path = dir.path / "rows.csv";
  const fs::path temporary = dir.path / "rows.csv.tmp";

  SECTION("a writer stopped by an exception leaves neither the file nor its temporary") {
    const auto write_half = [&] {
      WholeFile out = open_csv(dir.path, "rows.csv", "a,b");
      out << "1,2\n" << std::flush;
      CHECK(fs::exists(temporary));
      CHECK_FALSE(fs::exists(path));
      throw std::runtime_error("stopped");
    };
    CHECK_THROWS_WITH(write_half(), "stopped");
    CHECK_FALSE(fs::exists(path));
    CHECK_FALSE(fs::exists(temporary));
  }

  SECTION("a stopped rewrite leaves the earlier file as it was") {
    dda::verification::write_whole_file(path, "a,b\n0,0\n");
    const auto rewrite_half = [&] {
      WholeFile out(path);
      out << "a,b\n1,";
      throw std::runtime_error("stopped");
    };
    CHECK_THROWS(rewrite_half());
    CHECK(read_file(path) == "a,b\n0,0\n");
    CHECK_FALSE(fs::exists(temporary));
  }

  SECTION("a writer that finishes leaves the whole file, moved or not") {
    {
      WholeFile first = open_csv(dir.path, "rows.csv", "a,b");
      WholeFile out = std::move(first);
      out << "1,2\n3,4\n";
      out.finish();
      out.finish();  // a second call does nothing
    }
    CHECK(read_file(path) == "a,b\n1,2\n3,4\n");
    CHECK_FALSE(fs::exists(temporary));
  }

  SECTION("a writer that leaves its scope normally finishes the file") {
    {
      WholeFile out(path);
      out << "a,b\n5,6\n";
    }
    CHECK(read_file(path) == "a,b\n5,6\n");
    CHECK_FALSE(fs::exists(temporary));
  }

  SECTION("a failed write is an error naming the file and leaves nothing") {
    WholeFile out(path);
    out << "a,b\n";
    out.setstate(std::ios::badbit);
    CHECK_THROWS_WITH(out.finish(), "cannot write " + path.string());
    CHECK_FALSE(fs::exists(path));
    CHECK_FALSE(fs::exists(temporary));
  }

  SECTION("a failed rename is an error naming the file and leaves no temporary") {
    fs::create_directories(path / "in_the_way");  // a directory that a rename cannot replace
    WholeFile out(path);
    out << "a,b\n";
    CHECK_THROWS_WITH(out.finish(), Catch::Matchers::StartsWith("cannot write " + path.string()));
    CHECK(fs::is_directory(path / "in_the_way"));
    CHECK_FALSE(fs::exists(temporary));
  }
}
