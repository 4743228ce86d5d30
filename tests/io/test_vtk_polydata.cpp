// The VTK XML PolyData writer (io/vtk_polydata) and reader (io/vtk_reader): the ASCII text
// as earlier versions wrote it, the binary encoding's appended zlib blocks read by a decoder
// written here from the VTK file formats document (not by the reader under test), round
// trips through both encodings, empty and multi-block arrays, and malformed files refused.
#include <catch2/catch.hpp>

#include <bit>
#include <initializer_list>
#include <optional>
#include <utility>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <zlib.h>

#include "io/vtk_polydata.hpp"
#include "io/vtk_reader.hpp"
#include "support/cli_helpers.hpp"

using namespace dda;

namespace {

// Two blocks, a square and a triangle sharing no point, with cell data of the three types
// the blocks' series uses, and point data.
VtkPolyData two_polygons() {
  VtkPolyData p;
  p.points = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {2.0, 0.0}, {3.0, 0.5}, {2.5, 1e-7}};
  VtkCells polys;
  polys.connectivity = {0, 1, 2, 3, 4, 5, 6};
  polys.offsets = {4, 7};
  polys.ascii_own_line = true;
  p.polys = polys;
  p.cell_data.push_back({"block", VtkType::Int32, 1, {}, {0, 1}});
  p.cell_data.push_back({"fixed", VtkType::UInt8, 1, {}, {1, 0}});
  p.cell_data.push_back({"stress", VtkType::Float64, 3, {"sxx", "syy", "sxy"},
                         {-1e5, 0.1, 0.30000000000000004, 2.5, -0.0, 1e300}});
  p.point_data.push_back({"height", VtkType::Float64, 1, {}, {0, 0, 1, 1, 0, 0.5, 1e-7}});
  return p;
}

// Field by field: what a reader must give back (the ASCII layout flag aside, which binary
// files do not carry).
void check_same(const VtkPolyData& a, const VtkPolyData& b) {
  REQUIRE(a.points.size() == b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) CHECK(a.points[i] == b.points[i]);
  using Cells = std::pair<const std::optional<VtkCells>*, const std::optional<VtkCells>*>;
  for (const auto& [x, y] : std::initializer_list<Cells>{{&a.verts, &b.verts}, {&a.lines, &b.lines}, {&a.polys, &b.polys}}) {
    REQUIRE(x->has_value() == y->has_value());
    if (!*x) continue;
    CHECK((*x)->index_type == (*y)->index_type);
    CHECK((*x)->connectivity == (*y)->connectivity);
    CHECK((*x)->offsets == (*y)->offsets);
  }
  using Arrays = std::pair<const std::vector<VtkArray>*, const std::vector<VtkArray>*>;
  for (const auto& [x, y] : std::initializer_list<Arrays>{{&a.point_data, &b.point_data}, {&a.cell_data, &b.cell_data}}) {
    REQUIRE(x->size() == y->size());
    for (std::size_t k = 0; k < x->size(); ++k) {
      const VtkArray& u = (*x)[k];
      const VtkArray& v = (*y)[k];
      CHECK(u.name == v.name);
      CHECK(u.type == v.type);
      CHECK(u.components == v.components);
      CHECK(u.component_names == v.component_names);
      // Exact: ASCII writes the shortest text that reads back as the same double, binary
      // writes the bits.
      CHECK(u.values == v.values);
    }
  }
  CHECK(a.point_scalars == b.point_scalars);
  CHECK(a.cell_scalars == b.cell_scalars);
}

// ---- an independent decoder of VTK's appended, zlib-compressed arrays ----

std::uint64_t u64_at(const std::string& s, std::size_t at) {
  std::uint64_t v = 0;
  for (int k = 7; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(s[at + static_cast<std::size_t>(k)]);
  return v;
}

struct Decoded {
  std::vector<std::uint64_t> header;  // blocks, block size, last size, compressed sizes
  std::string bytes;                  // the blocks inflated, in order
};

// The array named `name` of a binary file: its offset attribute, then, from the byte after
// AppendedData's "_", the UInt64 header and each block inflated by zlib's uncompress.
Decoded decode_appended(const std::string& file, const std::string& name) {
  const std::size_t tag = file.find("Name=\"" + name + "\"");
  REQUIRE(tag != std::string::npos);
  const std::size_t attr = file.find("offset=\"", tag) + 8;
  const std::size_t offset = std::stoull(file.substr(attr, file.find('"', attr) - attr));
  const std::size_t base = file.find('_', file.find("<AppendedData encoding=\"raw\">")) + 1;
  Decoded d;
  const std::size_t at = base + offset;
  const std::uint64_t blocks = u64_at(file, at);
  for (std::uint64_t i = 0; i < 3 + blocks; ++i) d.header.push_back(u64_at(file, at + 8 * i));
  std::size_t data = at + 8 * (3 + blocks);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t size = (b + 1 == blocks && d.header[2] != 0) ? d.header[2] : d.header[1];
    std::string out(size, '\0');
    uLongf got = size;
    REQUIRE(uncompress(reinterpret_cast<Bytef*>(out.data()), &got,
                       reinterpret_cast<const Bytef*>(file.data() + data), d.header[3 + b]) == Z_OK);
    REQUIRE(got == size);
    d.bytes += out;
    data += d.header[3 + b];
  }
  return d;
}

// The little-endian bytes of doubles, as the file must hold them.
std::string le_doubles(const std::vector<double>& xs) {
  static_assert(std::endian::native == std::endian::little, "the test compares host bytes");
  std::string out(8 * xs.size(), '\0');
  if (!xs.empty()) std::memcpy(out.data(), xs.data(), out.size());
  return out;
}

}  // namespace

TEST_CASE("the ASCII encoding writes the text earlier versions wrote", "[vtk]") {
  VtkPolyData p;
  p.points = {{0.0, 0.0}, {1.0, 0.0}, {0.5, 1.0}};
  VtkCells polys;
  polys.connectivity = {0, 1, 2};
  polys.offsets = {3};
  polys.ascii_own_line = true;
  p.polys = polys;
  p.cell_data.push_back({"block", VtkType::Int32, 1, {}, {0}});
  p.cell_data.push_back({"stress", VtkType::Float64, 3, {"sxx", "syy", "sxy"}, {-1e5, 0.1, 100000}});
  // The blocks' frame of one triangle, character for character as vtp_text wrote it.
  CHECK(vtp_file(p, VtkEncoding::Ascii) ==
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        "  <PolyData>\n"
        "    <Piece NumberOfPoints=\"3\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"1\">\n"
        "      <Points>\n"
        "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
        "          0 0 0\n          1 0 0\n          0.5 1 0\n"
        "        </DataArray>\n      </Points>\n      <Polys>\n"
        "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n          0 1 2\n        </DataArray>\n"
        "        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n          3\n        </DataArray>\n"
        "      </Polys>\n      <CellData>\n"
        "        <DataArray type=\"Int32\" Name=\"block\" NumberOfComponents=\"1\" format=\"ascii\">\n          0\n        </DataArray>\n"
        "        <DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"3\" ComponentName0=\"sxx\" ComponentName1=\"syy\" ComponentName2=\"sxy\" format=\"ascii\">\n"
        "          -1e+05 0.1 1e+05\n        </DataArray>\n"
        "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n");
}

TEST_CASE("a piece reads back the same from its ASCII and its binary file", "[vtk]") {
  const VtkPolyData p = two_polygons();
  const VtkPolyData from_ascii = parse_vtp(vtp_file(p, VtkEncoding::Ascii), "a.vtp");
  const VtkPolyData from_binary = parse_vtp(vtp_file(p, VtkEncoding::Binary), "b.vtp");
  check_same(p, from_ascii);
  check_same(p, from_binary);
  CHECK(from_ascii.polys->ascii_own_line);
  // The reader's interface for a plot: arrays by name, polygons' points.
  REQUIRE(from_binary.find_cell_array("stress") != nullptr);
  CHECK(from_binary.find_cell_array("stress")->at(1, 2) == 1e300);
  CHECK(from_binary.find_point_array("stress") == nullptr);
  CHECK(from_binary.find_point_array("height")->at(6) == 1e-7);
  CHECK(from_binary.polygon(1) == std::vector<Vec2>{{2.0, 0.0}, {3.0, 0.5}, {2.5, 1e-7}});
  CHECK_THROWS_AS(from_binary.polygon(2), std::out_of_range);
  // Writing what was read gives the same file again, in either encoding.
  CHECK(vtp_file(from_ascii, VtkEncoding::Ascii) == vtp_file(p, VtkEncoding::Ascii));
  CHECK(vtp_file(from_binary, VtkEncoding::Binary) == vtp_file(p, VtkEncoding::Binary));
}

TEST_CASE("the binary file holds each array as VTK's zlib blocks of its little-endian bytes",
          "[vtk]") {
  const VtkPolyData p = two_polygons();
  const std::string file = vtp_file(p, VtkEncoding::Binary);
  CHECK(file.rfind("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
                   "byte_order=\"LittleEndian\" header_type=\"UInt64\" "
                   "compressor=\"vtkZLibDataCompressor\">\n", 0) == 0);
  CHECK(file.find("format=\"ascii\"") == std::string::npos);
  CHECK(file.ends_with("\n  </AppendedData>\n</VTKFile>\n"));

  const Decoded stress = decode_appended(file, "stress");
  // 6 doubles = 48 bytes: one partial block of 48 bytes.
  REQUIRE(stress.header.size() == 4);
  CHECK(stress.header[0] == 1);
  CHECK(stress.header[1] == kVtkBlockSize);
  CHECK(stress.header[2] == 48);
  CHECK(stress.bytes == le_doubles(p.cell_data[2].values));

  const Decoded block = decode_appended(file, "block");  // Int32 0, 1
  CHECK(block.bytes == std::string("\0\0\0\0\1\0\0\0", 8));
  const Decoded fixed = decode_appended(file, "fixed");  // UInt8 1, 0
  CHECK(fixed.bytes == std::string("\1\0", 2));
  const Decoded offsets = decode_appended(file, "offsets");  // Int32 4, 7
  CHECK(offsets.bytes == std::string("\4\0\0\0\7\0\0\0", 8));
}

TEST_CASE("an empty array is a header of no blocks, and a file of no contacts reads back",
          "[vtk]") {
  VtkPolyData p;
  p.verts = VtkCells{VtkType::Int64, {}, {}, false};
  p.point_scalars = "mode";
  p.point_data.push_back({"mode", VtkType::Int32, 1, {}, {}});
  p.point_data.push_back({"normal", VtkType::Float64, 3, {}, {}});
  const std::string file = vtp_file(p, VtkEncoding::Binary);
  const Decoded mode = decode_appended(file, "mode");
  // [0 blocks, the block size, 0]: what vtkXMLWriter writes for no data, and what
  // vtkXMLDataParser reads as zero words.
  CHECK(mode.header == std::vector<std::uint64_t>{0, kVtkBlockSize, 0});
  CHECK(mode.bytes.empty());
  const VtkPolyData back = parse_vtp(file, "empty.vtp");
  check_same(p, back);
  check_same(p, parse_vtp(vtp_file(p, VtkEncoding::Ascii), "empty-ascii.vtp"));
}

TEST_CASE("arrays longer than a block are split, the last block partial or full", "[vtk]") {
  SECTION("10000 doubles: two full blocks and 14464 bytes") {
    std::vector<double> xs(10000);
    for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = 0.001 * static_cast<double>(i * i) - 7.0;
    const std::string packed = vtk_compressed_array(le_doubles(xs));
    CHECK(u64_at(packed, 0) == 3);
    CHECK(u64_at(packed, 16) == 80000 - 2 * 32768);
    VtkPolyData p;
    p.points.resize(xs.size() / 2);
    for (std::size_t i = 0; i < p.points.size(); ++i) p.points[i] = Vec2(xs[2 * i], xs[2 * i + 1]);
    p.verts = VtkCells{VtkType::Int64, {}, {}, false};
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      p.verts->connectivity.push_back(static_cast<std::int64_t>(i));
      p.verts->offsets.push_back(static_cast<std::int64_t>(i + 1));
    }
    p.point_data.push_back({"x", VtkType::Float64, 1, {}, {}});
    for (const Vec2& q : p.points) p.point_data[0].values.push_back(q.x());
    const std::string file = vtp_file(p, VtkEncoding::Binary);
    const Decoded points = decode_appended(file, "x");
    CHECK(points.header[0] == 2);  // 5000 doubles = 40000 bytes
    CHECK(points.header[2] == 40000 - 32768);
    check_same(p, parse_vtp(file, "many.vtp"));
  }
  SECTION("exactly two blocks: the last size is 0 (every block full)") {
    // 8192 doubles of point data are 65536 bytes, two whole blocks.
    VtkPolyData p;
    p.points.resize(2 * kVtkBlockSize / 8, Vec2(0.25, -4.0));
    p.point_data.push_back({"v", VtkType::Float64, 1, {}, {}});
    for (std::size_t i = 0; i < p.points.size(); ++i) p.point_data[0].values.push_back(static_cast<double>(i) / 3.0);
    const std::string file = vtp_file(p, VtkEncoding::Binary);
    const Decoded v = decode_appended(file, "v");
    CHECK(v.header[0] == 2);
    CHECK(v.header[1] == kVtkBlockSize);
    CHECK(v.header[2] == 0);
    CHECK(v.bytes == le_doubles(p.point_data[0].values));
    check_same(p, parse_vtp(file, "full.vtp"));
  }
}

TEST_CASE("a malformed file is refused naming the file", "[vtk]") {
  const VtkPolyData p = two_polygons();
  const std::string binary = vtp_file(p, VtkEncoding::Binary);
  const std::string ascii = vtp_file(p, VtkEncoding::Ascii);
  // Cut inside the appended data.
  CHECK_THROWS_WITH(parse_vtp(binary.substr(0, binary.size() - 60), "cut.vtp"),
                    Catch::Contains("cut.vtp"));
  // A compressed byte changed: zlib's check fails or the size is wrong.
  std::string corrupt = binary;
  const std::size_t base = corrupt.find('_', corrupt.find("<AppendedData")) + 1;
  corrupt[base + 8 * 4 + 3] = static_cast<char>(corrupt[base + 8 * 4 + 3] ^ 0x5A);
  CHECK_THROWS_WITH(parse_vtp(corrupt, "corrupt.vtp"), Catch::Contains("corrupt.vtp") &&
                                                           Catch::Contains("inflate"));
  // An ASCII array one value short.
  std::string short_array = ascii;
  short_array.replace(short_array.find("          1e-07\n        </DataArray>"), 16, "");
  CHECK_THROWS_WITH(parse_vtp(short_array, "short.vtp"),
                    Catch::Contains("short.vtp") && Catch::Contains("\"height\" holds 6 numbers"));
  // A point index past the points.
  std::string bad_index = ascii;
  bad_index.replace(bad_index.find("0 1 2 3 4 5 6"), 13, "0 1 2 3 4 5 9");
  CHECK_THROWS_WITH(parse_vtp(bad_index, "index.vtp"), Catch::Contains("use point 9 of 7"));
  CHECK_THROWS_WITH(parse_vtp("not xml at all", "text.vtp"), Catch::Contains("text.vtp"));
  CHECK_THROWS_WITH(read_vtp("/nonexistent/frame.vtp"), Catch::Contains("/nonexistent/frame.vtp"));
}
