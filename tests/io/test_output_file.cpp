// Output files that fail whole or not at all (io/output_file.hpp).
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

#include "io/output_file.hpp"
#include "support/cli_helpers.hpp"

namespace fs = std::filesystem;
using dda::OutputTarget;

namespace {

// Runs `body` in a child process under a file-size limit of `bytes` with SIGXFSZ ignored (as
// dda's main does); the child's exit code: 0 when `body` returned, 10 when it threw, 20 for
// anything else. The limit stays in the child.
int with_file_size_limit(rlim_t bytes, const std::function<void()>& body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{bytes, bytes};
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(20);
    try {
      body();
    } catch (const std::runtime_error&) {
      ::_exit(10);
    } catch (...) {
      ::_exit(20);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("check_output_file tells files to replace from streams and refuses the rest", "[io][output]") {
  const dda::test::TempDir dir("dda-output-file-");
  CHECK(dda::check_output_file(dir.path / "none") == OutputTarget::Absent);
  dda::test::write_file(dir.path / "file", "x");
  CHECK(dda::check_output_file(dir.path / "file") == OutputTarget::Regular);
  CHECK(dda::check_output_file("/dev/null") == OutputTarget::Stream);
  REQUIRE(::mkfifo((dir.path / "fifo").c_str(), 0644) == 0);
  CHECK(dda::check_output_file(dir.path / "fifo") == OutputTarget::Stream);
  fs::create_symlink("/dev/full", dir.path / "link");
  CHECK(dda::check_output_file(dir.path / "link") == OutputTarget::Stream);
  CHECK_THROWS_WITH(dda::check_output_file(dir.path),
                    Catch::Contains(dir.path.string() + " is a directory"));
}

TEST_CASE("write_file_whole replaces a file through a link, and leaves nothing when it fails",
          "[io][output]") {
  const dda::test::TempDir dir("dda-output-file-");
  const fs::path target = dir.path / "target.json";
  dda::test::write_file(target, "old\n");
  fs::create_symlink(target, dir.path / "link.json");
  dda::write_file_whole(dir.path / "link.json", "new\n");
  CHECK(fs::is_symlink(dir.path / "link.json"));  // the link stays, its file is replaced
  CHECK(dda::test::read_file(target) == "new\n");
  CHECK_FALSE(fs::exists(dir.path / "target.json.tmp"));

  // Into a full device: an error naming the path and the reason, the device left alone.
  CHECK_THROWS_WITH(dda::write_file_whole("/dev/full", "x"),
                    Catch::Contains("cannot write /dev/full (No space left on device)"));
  // A temporary name held by something other than a file: refused, the file as it was.
  fs::create_directories(dir.path / "target.json.tmp");
  CHECK_THROWS_WITH(dda::write_file_whole(target, "newer\n"), Catch::Contains("is in the way"));
  CHECK(dda::test::read_file(target) == "new\n");
  fs::remove(dir.path / "target.json.tmp");

  // Beyond a file-size limit of 100 bytes: the old file stays, no temporary file is left.
  CHECK(with_file_size_limit(100, [&] { dda::write_file_whole(target, std::string(1000, 'x')); }) == 10);
  CHECK(dda::test::read_file(target) == "new\n");
  CHECK_FALSE(fs::exists(dir.path / "target.json.tmp"));
}

TEST_CASE("a streamed file ends with its last whole record when a write fails", "[io][output]") {
  const dda::test::TempDir dir("dda-output-file-");
  const fs::path csv = dir.path / "rows.csv";
  // Records of 3 rows of 10 bytes under a limit of 100 bytes: the header (5 bytes) and
  // three records (90 bytes) fit, the fourth is cut back.
  const int code = with_file_size_limit(100, [&] {
    dda::StreamedFile f(csv, "head\n");
    for (int k = 0; k < 10; ++k) {
      for (int row = 0; row < 3; ++row) f.append("012345678\n");
      f.commit();
    }
  });
  CHECK(code == 10);
  std::string expected = "head\n";
  for (int k = 0; k < 9; ++k) expected += "012345678\n";
  CHECK(dda::test::read_file(csv) == expected);
  // A header that cannot be written leaves no file.
  CHECK(with_file_size_limit(3, [&] { dda::StreamedFile f(dir.path / "none.csv", "header\n"); }) == 10);
  CHECK_FALSE(fs::exists(dir.path / "none.csv"));
  // The error names the file and says what is kept.
  CHECK_THROWS_WITH(dda::StreamedFile("/dev/full", "header\n"),
                    Catch::Contains("cannot write /dev/full (No space left on device)"));
}
