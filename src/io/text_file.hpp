// Writing a whole text file so that nothing is ever left half written under its final name.
#pragma once

#include <string>

namespace dda {

// Writes `text` to `path` through a temporary file (path + ".tmp") and a rename: a reader,
// or a run that dies half-way, sees the old file or the new one, never a part. Throws
// std::runtime_error naming the file when it cannot, and then leaves no temporary file
// (io/output_file.hpp, write_file_whole).
void write_text_file(const std::string& path, const std::string& text);

}  // namespace dda
