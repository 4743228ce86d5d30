#include "io/text_file.hpp"

#include "io/output_file.hpp"

namespace dda {

void write_text_file(const std::string& path, const std::string& text) {
  write_file_whole(path, text);
}

}  // namespace dda
