// Files that appear under their final name only when whole. The verification programs
// follow the rule the dda command line follows (src/io/output_file.hpp): a run that stops
// keeps what it wrote, complete, and nothing is written half under its final name. A
// program stopped part way, by an exception or a failed write, leaves the files it finished
// and no part of the others; an earlier file under the same name is left as it was.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace dda::verification {

// An output stream into NAME.tmp beside the final path NAME, renamed to NAME when finished.
// finish() does it and throws when it cannot, so that a program can report the failure
// like any other write failure; the destructor finishes a file that was not finished if the
// stream is good and no exception is unwinding past it, and otherwise closes and removes the
// temporary, so that an early exit never leaves a part of a file under its final name.
// Movable, so that a helper can open and return one (open_csv).
class WholeFile : public std::ofstream {
 public:
  // Opens (empties) PATH.tmp for writing. Like std::ofstream, a file that cannot be opened
  // leaves the stream failed rather than throwing; finish() then throws.
  explicit WholeFile(std::filesystem::path path);
  WholeFile(WholeFile&& other) noexcept;
  // Abandons the file this one was writing, if any, before taking over `other`'s.
  WholeFile& operator=(WholeFile&& other) noexcept;
  WholeFile(const WholeFile&) = delete;
  WholeFile& operator=(const WholeFile&) = delete;
  ~WholeFile() override;

  // Flushes and closes the temporary and renames it to the final name. When the stream has
  // failed (or was never opened), or the close or the rename fails, removes the temporary and
  // throws std::runtime_error("cannot write PATH", with the system's reason for a failed
  // rename). A second call after a successful one does nothing.
  void finish();

  // Closes and removes the temporary; the final name is left as it was.
  void abandon() noexcept;

  const std::filesystem::path& path() const noexcept { return path_; }

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  bool pending_ = false;   // the temporary exists and is neither renamed nor removed
  bool finished_ = false;  // renamed to the final name
  // std::uncaught_exceptions() when opened: more at destruction means an exception is
  // unwinding through the scope that wrote the file, which then is not whole.
  int uncaught_at_open_ = 0;
};

// Writes `text` as the whole file `path` through a WholeFile; throws std::runtime_error
// ("cannot write PATH") when it cannot.
void write_whole_file(const std::filesystem::path& path, const std::string& text);

}  // namespace dda::verification
