// The CSV of `dda material-point` (docs/material-point-format.md): one row per increment
// plus step 0, header `step,exx,eyy,gxy,sxx,syy,szz,sxy,eps_p,branch`.
#pragma once

#include <filesystem>
#include <fstream>
#include <span>

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

  // Appends one row (buffered: flush() writes it out). Throws when the stream has failed.
  void write_row(const MaterialPointRow& row);
  void flush();

 private:
  std::filesystem::path path_;
  std::ofstream out_;
};

}  // namespace dda
