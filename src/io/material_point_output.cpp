#include "io/material_point_output.hpp"

#include <stdexcept>
#include <system_error>
#include <utility>

#include "io/output.hpp"

namespace dda {

namespace {

[[noreturn]] void fail(const std::string& what, const std::filesystem::path& path) {
  throw std::runtime_error("output: " + what + " " + path.string());
}

}  // namespace

MaterialPointCsv::MaterialPointCsv(std::filesystem::path path) : path_(std::move(path)) {
  const std::filesystem::path parent = path_.parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);
    if (ec) fail("cannot create directory (" + ec.message() + ")", parent);
  }
  out_.open(path_, std::ios::trunc);
  if (!out_) fail("cannot open", path_);
  out_ << kMaterialPointHeader << '\n';
  out_.flush();
  if (!out_) fail("cannot write", path_);
}

void MaterialPointCsv::write(std::span<const MaterialPointRow> rows) {
  for (const MaterialPointRow& row : rows) write_row(row);
  flush();
}

void MaterialPointCsv::write_row(const MaterialPointRow& row) {
  out_ << row.step;
  for (int i = 0; i < 3; ++i) out_ << ',' << format_full_precision(row.strain[i]);
  for (int i = 0; i < 4; ++i) out_ << ',' << format_full_precision(row.stress[i]);
  out_ << ',' << format_full_precision(row.state.eps_p) << ',' << branch_name(row.branch) << '\n';
  if (!out_) fail("cannot write", path_);
}

void MaterialPointCsv::flush() {
  out_.flush();
  if (!out_) fail("cannot write", path_);
}

}  // namespace dda
