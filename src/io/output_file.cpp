#include "io/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace dda {
namespace {

namespace fs = std::filesystem;

// The system's reason, with what it means for a results file.
std::string reason(int err) {
  std::string text = std::strerror(err);
  if (err == EFBIG) text += ": the file-size limit (ulimit -f) or the file system's";
  return text;
}

// Writes all of `bytes` (short writes continued, EINTR retried); 0 or the errno that stopped it.
int write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

[[noreturn]] void fail(const fs::path& path, const std::string& why, const std::string& kept) {
  throw std::runtime_error("output: cannot write " + path.string() + " (" + why + ")" + kept);
}

constexpr const char* kNotReplaced = "; nothing of it was kept (a file of that name from before stays as it was)";

// The path a chain of symbolic links ends at (relative targets taken from each link's
// directory), or `path` itself when it is no link; at most 40 links followed, as the kernel.
fs::path named_by_links(const fs::path& path) {
  fs::path at = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(at.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return at;
    std::error_code ec;
    const fs::path target = fs::read_symlink(at, ec);
    if (ec) return at;
    at = target.is_absolute() ? target : at.parent_path() / target;
  }
  return at;
}

}  // namespace

OutputTarget check_output_file(const fs::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return OutputTarget::Absent;
  if (S_ISREG(st.st_mode)) return OutputTarget::Regular;
  if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return OutputTarget::Stream;
  const char* what = S_ISDIR(st.st_mode)    ? "a directory"
                     : S_ISBLK(st.st_mode)  ? "a block device"
                     : S_ISSOCK(st.st_mode) ? "a socket"
                                            : "not a regular file";
  throw std::runtime_error("output: " + path.string() + " is " + what +
                           "; dda writes its results as regular files (or into a character "
                           "device or FIFO) and does not replace it");
}

void write_file_whole(const fs::path& path, std::string_view bytes) {
  const OutputTarget target = check_output_file(path);
  if (target == OutputTarget::Stream) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) fail(path, reason(errno), "");
    int err = write_all(fd, bytes);
    if (::close(fd) != 0 && err == 0) err = errno;
    if (err != 0) fail(path, reason(err), "");
    return;
  }
  // A symbolic link stays a link: the file it names is replaced, or created when the link
  // names nothing yet (a dangling link was once replaced by a regular file).
  const fs::path real = named_by_links(path);
  const fs::path tmp = real.string() + ".tmp";
  struct stat st {};
  if (::lstat(tmp.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    fail(path, "its temporary file " + tmp.string() + " is in the way and not a regular file",
         kNotReplaced);
  }
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) {
    fail(path, "cannot create its temporary file " + tmp.string() + ": " + reason(errno),
         kNotReplaced);
  }
  int err = write_all(fd, bytes);
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && ::rename(tmp.c_str(), real.c_str()) != 0) err = errno;
  if (err != 0) {
    ::unlink(tmp.c_str());
    fail(path, reason(err), kNotReplaced);
  }
}

void prepare_output_directory(const fs::path& dir, std::initializer_list<const char*> names) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    throw std::runtime_error("output: cannot create directory " + dir.string() + " (" +
                             ec.message() + ")");
  }
  for (const char* name : names) check_output_file(dir / name);
  const fs::path probe = dir / (".dda-probe-" + std::to_string(::getpid()));
  write_file_whole(probe, "dda checks that it can write here\n");
  ::unlink(probe.c_str());
}

StreamedFile::StreamedFile(fs::path path, std::string_view header) : path_(std::move(path)) {
  regular_ = check_output_file(path_) != OutputTarget::Stream;
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC | (regular_ ? O_CREAT | O_TRUNC : 0), 0666);
  if (fd_ < 0) fail(path_, "cannot open it: " + reason(errno), "");
  const int err = write_all(fd_, header);
  if (err != 0) {
    ::close(fd_);
    fd_ = -1;
    if (regular_) ::unlink(path_.c_str());
    fail(path_, reason(err), regular_ ? "; no file was left under that name" : "");
  }
  committed_ = static_cast<long long>(header.size());
  digest_ = continue_digest(kDigestStart, header);
}

StreamedFile::StreamedFile(fs::path path, const StreamProgress& at) : path_(std::move(path)) {
  regular_ = true;
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd_ < 0) fail(path_, "cannot open it: " + reason(errno), "");
  const auto length = static_cast<off_t>(at.bytes);
  if (::ftruncate(fd_, length) != 0 || ::lseek(fd_, length, SEEK_SET) < 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    fail(path_, "cannot cut it back to the checkpoint's step: " + reason(err), "");
  }
  committed_ = static_cast<long long>(at.bytes);
  digest_ = at.digest;
}

bool file_begins_with(const fs::path& path, const StreamProgress& progress) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::uint64_t digest = kDigestStart;
  std::uint64_t left = progress.bytes;
  std::string buffer(1 << 16, '\0');
  while (left > 0) {
    const auto want = static_cast<std::streamsize>(std::min<std::uint64_t>(left, buffer.size()));
    in.read(buffer.data(), want);
    if (in.gcount() != want) return false;  // shorter than the checkpoint's
    digest = continue_digest(digest, std::string_view(buffer.data(), static_cast<std::size_t>(want)));
    left -= static_cast<std::uint64_t>(want);
  }
  return digest == progress.digest;
}

StreamedFile::~StreamedFile() {
  if (fd_ >= 0) ::close(fd_);
}

void StreamedFile::commit() {
  if (pending_.empty()) return;
  const int err = write_all(fd_, pending_);
  if (err == 0) {
    committed_ += static_cast<long long>(pending_.size());
    digest_ = continue_digest(digest_, pending_);
    pending_.clear();
    return;
  }
  pending_.clear();
  std::string kept;
  if (regular_) {
    // Back to the end of the last whole record: a file-size limit or a full disk may have
    // taken part of this one.
    if (::ftruncate(fd_, static_cast<off_t>(committed_)) == 0 &&
        ::lseek(fd_, static_cast<off_t>(committed_), SEEK_SET) >= 0) {
      kept = "; it was cut back to the end of its last whole row";
    } else {
      kept = std::string("; cutting it back to its last whole row failed too (") +
             std::strerror(errno) + ")";
    }
  }
  fail(path_, reason(err), kept);
}

}  // namespace dda
