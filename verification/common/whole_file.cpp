#include "whole_file.hpp"

#include <exception>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace dda::verification {

WholeFile::WholeFile(std::filesystem::path path)
    : path_(std::move(path)),
      temporary_(path_.string() + ".tmp"),
      uncaught_at_open_(std::uncaught_exceptions()) {
  open(temporary_, std::ios::out | std::ios::trunc);
  pending_ = is_open();
}

WholeFile::WholeFile(WholeFile&& other) noexcept
    : std::ofstream(std::move(other)),
      path_(std::move(other.path_)),
      temporary_(std::move(other.temporary_)),
      pending_(std::exchange(other.pending_, false)),
      finished_(other.finished_),
      uncaught_at_open_(other.uncaught_at_open_) {}

WholeFile& WholeFile::operator=(WholeFile&& other) noexcept {
  if (this != &other) {
    abandon();
    std::ofstream::operator=(std::move(other));
    path_ = std::move(other.path_);
    temporary_ = std::move(other.temporary_);
    pending_ = std::exchange(other.pending_, false);
    finished_ = other.finished_;
    uncaught_at_open_ = other.uncaught_at_open_;
  }
  return *this;
}

WholeFile::~WholeFile() {
  if (!pending_) return;
  if (good() && std::uncaught_exceptions() <= uncaught_at_open_) {
    try {
      finish();
    } catch (const std::exception&) {
      // finish() has removed the temporary; a destructor has no one to tell, which is why
      // the programs call finish() themselves.
    }
  } else {
    abandon();
  }
}

void WholeFile::finish() {
  if (finished_) return;
  std::error_code ec;
  if (pending_) {
    flush();
    close();  // sets failbit when the last bytes cannot be written
    pending_ = false;
    if (!fail()) {
      std::filesystem::rename(temporary_, path_, ec);
      if (!ec) {
        finished_ = true;
        return;
      }
    }
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
  throw std::runtime_error("cannot write " + path_.string() + (ec ? ": " + ec.message() : ""));
}

void WholeFile::abandon() noexcept {
  if (!pending_) return;
  pending_ = false;
  close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void write_whole_file(const std::filesystem::path& path, const std::string& text) {
  WholeFile out(path);
  out << text;
  out.finish();
}

}  // namespace dda::verification
