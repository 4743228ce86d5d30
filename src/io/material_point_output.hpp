// The CSV of `dda material-point` (docs/material-point-format.md): one row per increment
// plus step 0, header `step,exx,eyy,gxy,sxx,syy,szz,sxy,eps_p,branch`.
#pragma once

#include <filesystem>
#include <optional>
#include <span>

#include "io/output_file.hpp"

#include "materials/material_point.hpp"

namespace dda {

inline constexpr const char* kMaterialPointHeader = "step,exx,eyy,gxy,sxx,syy,szz,sxy,eps_p,branch";

class MaterialPointCsv {
 public:
  // Creates the parent directory if needed, opens `path` and writes the header, so that an
  // unwritable path is known before the path is run. Throws std::runtime_error naming it.
  explicit MaterialPointCsv(std::filesystem::path path);

  // Appends the rows and flushes. Throws std::runtime_error when the file cannot be written.
  void write(std::span<const MaterialPointRow> rows);

  // Appends one row (held until flush() writes the rows held, whole).
  void write_row(const MaterialPointRow& row);
  // Writes the rows held. A write that fails (full disk, file-size limit) throws naming the
  // file, which is then cut back to the rows of the flush before (StreamedFile).
  void flush();

 private:
  std::filesystem::path path_;
  std::optional<StreamedFile> out_;
};

}  // namespace dda
