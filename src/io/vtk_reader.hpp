// Reading back the VTK XML PolyData files this code writes (io/vtk_polydata.hpp), in either
// encoding: format="ascii" arrays, and format="appended" arrays raw after the XML, zlib-
// compressed (compressor="vtkZLibDataCompressor") or not, with UInt32 or UInt64 headers.
// Not a general VTK reader: one piece, no strips, the four types VtkType names, no base64.
#pragma once

#include <filesystem>
#include <string>

#include "io/vtk_polydata.hpp"

namespace dda {

// The file's piece. Throws std::runtime_error naming the file and what is wrong on anything
// malformed: a missing or short array, a count the piece does not declare, an offset or
// index out of range, a block that does not inflate to its declared size.
VtkPolyData read_vtp(const std::filesystem::path& path);

// The same from the file's bytes; `name` is the file name the messages give.
VtkPolyData parse_vtp(const std::string& bytes, const std::string& name);

}  // namespace dda
