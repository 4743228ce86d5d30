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
  out_.emplace(path_, std::string(kMaterialPointHeader) + "\n");
}

void MaterialPointCsv::write(std::span<const MaterialPointRow> rows) {
  for (const MaterialPointRow& row : rows) write_row(row);
  flush();
}

void MaterialPointCsv::write_row(const MaterialPointRow& row) {
  StreamedFile& out = *out_;
  out.append(std::to_string(row.step));
  const auto put = [&out](double x) {
    out.append(',');
    out.append(format_full_precision(x));
  };
  for (int i = 0; i < 3; ++i) put(row.strain[i]);
  for (int i = 0; i < 4; ++i) put(row.stress[i]);
  put(row.state.eps_p);
  out.append(',');
  out.append(branch_name(row.branch));
  out.append('\n');
}

void MaterialPointCsv::flush() { out_->commit(); }

}  // namespace dda
