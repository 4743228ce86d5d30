// Output files that fail whole or not at all (docs/output-format.md "When a file
// cannot be written"): what is at an output path is checked before it is written over,
// whole files go to a temporary name beside their final one and are renamed into place
// when complete, and streamed files (history.csv, monitors.csv, the material-point CSV)
// grow by whole rows and are cut back to their last whole row when a write fails (a full
// disk, ENOSPC; a file-size limit, EFBIG: main ignores SIGXFSZ so that the limit is an
// error here rather than the end of the program).
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace dda {

// What an output file's path holds (symbolic links followed).
enum class OutputTarget {
  Absent,   // nothing (or something that cannot be looked at: opening it will say why)
  Regular,  // a regular file: replaced whole, by a rename
  Stream,   // a character device (/dev/null, a terminal) or a FIFO: written into, never replaced
};

// Throws std::runtime_error ("output: ... PATH") when `path` holds what dda must not write
// over or into: a directory, a block device, a socket.
OutputTarget check_output_file(const std::filesystem::path& path);

// Writes `bytes` as the whole file `path`: into PATH.tmp beside it (beside the file a
// symbolic link names), then renamed over it. On failure the temporary file is removed and
// std::runtime_error names `path` and the system's reason; an earlier file under that name
// is left as it was. A character device or FIFO is written into directly.
void write_file_whole(const std::filesystem::path& path, std::string_view bytes);

// Before a long command's work: creates `dir` if needed, checks that none of `names`
// inside it holds what check_output_file refuses, and writes and removes a probe file
// there, so that an unwritable directory is known before the work rather than after it.
// Throws std::runtime_error naming the path.
void prepare_output_directory(const std::filesystem::path& dir,
                              std::initializer_list<const char*> names);

// FNV-1a, 64 bits: a digest of bytes, continued over pieces (`digest` the pieces' so far,
// kDigestStart for none). What a checkpoint checks a streamed file and its own payload by:
// it tells a file cut short or another run's file from the one it was, not a forgery.
inline constexpr std::uint64_t kDigestStart = 14695981039346656037ull;
inline std::uint64_t continue_digest(std::uint64_t digest, std::string_view bytes) {
  for (const char c : bytes) {
    digest ^= static_cast<unsigned char>(c);
    digest *= 1099511628211ull;
  }
  return digest;
}

// How far a streamed file had been written: its bytes of whole records and their digest.
struct StreamProgress {
  std::uint64_t bytes = 0;
  std::uint64_t digest = kDigestStart;
};

// Whether the file at `path` begins with the bytes `progress` describes.
bool file_begins_with(const std::filesystem::path& path, const StreamProgress& progress);

// A file written as a run goes, in records of whole rows: append() gathers a record,
// commit() writes it. A commit that fails (full disk, file-size limit) cuts the file back
// to the end of the last record written and throws std::runtime_error naming the file and
// the reason, so that the file never ends in a part of a row.
class StreamedFile {
 public:
  // Creates (or empties) `path` and writes `header` (a whole line) as the first record. A
  // header that cannot be written leaves no file behind. Throws naming the path.
  StreamedFile(std::filesystem::path path, std::string_view header);
  // Continues the regular file `path` (a restarted run's), cut back to `at`, which the caller
  // has checked it begins with (file_begins_with). Throws naming the path.
  StreamedFile(std::filesystem::path path, const StreamProgress& at);
  ~StreamedFile();
  StreamedFile(const StreamedFile&) = delete;
  StreamedFile& operator=(const StreamedFile&) = delete;

  void append(std::string_view text) { pending_ += text; }
  void append(char c) { pending_ += c; }
  void commit();
  const std::filesystem::path& path() const { return path_; }
  // The whole records written so far.
  StreamProgress progress() const { return {static_cast<std::uint64_t>(committed_), digest_}; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  bool regular_ = false;
  long long committed_ = 0;  // bytes of whole records in the file
  std::uint64_t digest_ = kDigestStart;  // of those bytes
  std::string pending_;
};

}  // namespace dda
