// One piece of VTK XML PolyData as plain data, and its file text (docs/output-format.md,
// "VTK frames: encoding"). Every VTK series of a run (blocks, contacts, bolts) fills a VtkPolyData and
// writes it here; io/vtk_reader.hpp reads the files back into the same struct.
//
// The layout follows "VTK File Formats" (the VTK User's Guide, XML file formats, PolyData):
// a <Piece> of points, then the cells of each kind (Verts, Lines, Polys) as a connectivity
// and an offsets array, then point data and cell data arrays.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kinematics/types.hpp"

namespace dda {

// How a file's arrays are stored. Binary is ParaView's own default: every array appended raw
// after the XML, zlib-compressed in blocks; ASCII is the readable text earlier versions wrote.
enum class VtkEncoding { Binary, Ascii };

// The DataArray types this code writes (VTK's names).
enum class VtkType { Int32, Int64, UInt8, Float64 };

const char* vtk_type_name(VtkType type);

// A point or cell data array: `values` holds `components` numbers per tuple, tuple after
// tuple. Integer types hold whole numbers (every Int32 and UInt8 value is exact as a double).
struct VtkArray {
  std::string name;
  VtkType type = VtkType::Float64;
  int components = 1;
  std::vector<std::string> component_names;  // empty, or one per component (ParaView's menus)
  std::vector<double> values;

  std::size_t tuples() const { return values.size() / static_cast<std::size_t>(components); }
  double at(std::size_t tuple, int component = 0) const {
    return values[tuple * static_cast<std::size_t>(components) + static_cast<std::size_t>(component)];
  }
};

// Cells of one kind: cell i uses the points connectivity[offsets[i-1] .. offsets[i]) (from 0
// for the first), as VTK's XML PolyData stores them.
struct VtkCells {
  VtkType index_type = VtkType::Int32;  // Int32 or Int64 (what the file declares)
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;
  // The ASCII text only: the indices on a line of their own (the blocks' layout) rather
  // than inside the element (the contacts' and bolts'); kept so that the ASCII files stay
  // as earlier versions wrote them, byte for byte.
  bool ascii_own_line = false;

  std::size_t size() const { return offsets.size(); }
};

struct VtkPolyData {
  std::vector<Vec2> points;  // z is 0 in the file
  std::optional<VtkCells> verts, lines, polys;  // a kind absent from the piece is nullopt
  std::vector<VtkArray> point_data, cell_data;
  std::string point_scalars, cell_scalars;  // the sections' Scalars attribute ("" for none)

  std::size_t cells() const;  // verts + lines + polys: the tuples of each cell data array
  // The array of that name, or nullptr.
  const VtkArray* find_point_array(const std::string& name) const;
  const VtkArray* find_cell_array(const std::string& name) const;
  // The points of polygon i, in order. Throws std::out_of_range for a bad i.
  std::vector<Vec2> polygon(std::size_t i) const;
};

// The whole .vtp file. ASCII gives the same text as earlier versions (format="ascii",
// numbers as format_full_precision writes them); binary gives header_type="UInt64",
// compressor="vtkZLibDataCompressor" and every array appended.
std::string vtp_file(const VtkPolyData& piece, VtkEncoding encoding);

// The uncompressed block size of the binary encoding: VTK's own writer's default
// (vtkXMLWriter, BlockSize 32768 bytes).
inline constexpr std::size_t kVtkBlockSize = 32768;

// One array's appended bytes in VTK's compressed layout: a UInt64 header [number of blocks,
// uncompressed block size, uncompressed size of the last block if partial (else 0),
// compressed size of each block], then each block as one zlib stream. `raw` is the array's
// little-endian bytes. Public for the tests.
std::string vtk_compressed_array(const std::string& raw, std::size_t block_size = kVtkBlockSize);

}  // namespace dda
