#include "io/vtk_polydata.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include <zlib.h>

#include "io/output.hpp"

namespace dda {

const char* vtk_type_name(VtkType type) {
  switch (type) {
    case VtkType::Int32: return "Int32";
    case VtkType::Int64: return "Int64";
    case VtkType::UInt8: return "UInt8";
    case VtkType::Float64: return "Float64";
  }
  return "Float64";
}

std::size_t VtkPolyData::cells() const {
  std::size_t n = 0;
  for (const std::optional<VtkCells>* c : {&verts, &lines, &polys}) {
    if (*c) n += (*c)->size();
  }
  return n;
}

namespace {

const VtkArray* find_array(const std::vector<VtkArray>& arrays, const std::string& name) {
  for (const VtkArray& a : arrays) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

// ---- the little-endian bytes of an array (the file says byte_order="LittleEndian") ----

void put_le(std::string& out, std::uint64_t bits, int bytes) {
  for (int k = 0; k < bytes; ++k) out += static_cast<char>((bits >> (8 * k)) & 0xFFu);
}

void put_value(std::string& out, VtkType type, double v) {
  switch (type) {
    case VtkType::Int32:
      put_le(out, static_cast<std::uint32_t>(static_cast<std::int32_t>(v)), 4);
      break;
    case VtkType::Int64:
      put_le(out, static_cast<std::uint64_t>(static_cast<std::int64_t>(v)), 8);
      break;
    case VtkType::UInt8: put_le(out, static_cast<std::uint8_t>(v), 1); break;
    case VtkType::Float64: put_le(out, std::bit_cast<std::uint64_t>(v), 8); break;
  }
}

std::string raw_bytes(VtkType type, const std::vector<double>& values) {
  std::string out;
  for (double v : values) put_value(out, type, v);
  return out;
}

std::string raw_indices(VtkType type, const std::vector<std::int64_t>& values) {
  std::string out;
  for (std::int64_t v : values) {
    put_le(out, static_cast<std::uint64_t>(v), type == VtkType::Int32 ? 4 : 8);
  }
  return out;
}

// ---- the text of one number ----

std::string text_of(VtkType type, double v) {
  if (type == VtkType::Float64) return format_full_precision(v);
  return std::to_string(static_cast<long long>(v));
}

// ---- the XML around the arrays ----

// Where the arrays go: their text (ASCII) or the appended section and its offsets (binary).
class ArraySink {
 public:
  explicit ArraySink(VtkEncoding encoding) : encoding_(encoding) {}
  bool ascii() const { return encoding_ == VtkEncoding::Ascii; }

  // Ends a DataArray's opening tag: the format, and for binary the offset of its bytes in
  // the appended section (from the byte after "_", as the file formats document says).
  void close_tag(std::string& s, const std::string& raw) {
    if (ascii()) {
      s += " format=\"ascii\">";
      return;
    }
    s += " format=\"appended\" offset=\"" + std::to_string(appended_.size()) + "\"/>\n";
    appended_ += vtk_compressed_array(raw);
  }
  const std::string& appended() const { return appended_; }

 private:
  VtkEncoding encoding_;
  std::string appended_;
};

std::string opening(const VtkPolyData& p, VtkEncoding encoding) {
  auto count = [](const std::optional<VtkCells>& c) { return std::to_string(c ? c->size() : 0); };
  std::string s = "<?xml version=\"1.0\"?>\n";
  // header_type="UInt64" needs version 1.0; the ASCII files keep the 0.1 they always had.
  s += encoding == VtkEncoding::Ascii
           ? "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           : "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
             "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n";
  s += "  <PolyData>\n";
  s += "    <Piece NumberOfPoints=\"" + std::to_string(p.points.size()) + "\" NumberOfVerts=\"" +
       count(p.verts) + "\" NumberOfLines=\"" + count(p.lines) +
       "\" NumberOfStrips=\"0\" NumberOfPolys=\"" + count(p.polys) + "\">\n";
  return s;
}

void write_points(std::string& s, const VtkPolyData& p, ArraySink& sink) {
  s += "      <Points>\n";
  s += "        <DataArray type=\"Float64\" NumberOfComponents=\"3\"";
  std::string raw;
  if (!sink.ascii()) {
    for (const Vec2& q : p.points) {
      for (double v : {q.x(), q.y(), 0.0}) put_value(raw, VtkType::Float64, v);
    }
  }
  sink.close_tag(s, raw);
  if (sink.ascii()) {
    s += "\n";
    for (const Vec2& q : p.points) {
      s += "          " + format_full_precision(q.x()) + " " + format_full_precision(q.y()) + " 0\n";
    }
    s += "        </DataArray>\n";
  }
  s += "      </Points>\n";
}

void write_index_array(std::string& s, const VtkCells& c, const char* name,
                       const std::vector<std::int64_t>& values, ArraySink& sink) {
  s += "        <DataArray type=\"";
  s += vtk_type_name(c.index_type);
  s += "\" Name=\"";
  s += name;
  s += "\"";
  sink.close_tag(s, sink.ascii() ? std::string() : raw_indices(c.index_type, values));
  if (!sink.ascii()) return;
  std::string text;
  for (std::int64_t v : values) {
    text += ' ';
    text += std::to_string(v);
  }
  if (c.ascii_own_line) {
    s += "\n         " + text + "\n        </DataArray>\n";
  } else {
    s += text + "</DataArray>\n";
  }
}

void write_cells(std::string& s, const std::optional<VtkCells>& c, const char* section,
                 ArraySink& sink) {
  if (!c) return;
  s += "      <" + std::string(section) + ">\n";
  write_index_array(s, *c, "connectivity", c->connectivity, sink);
  write_index_array(s, *c, "offsets", c->offsets, sink);
  s += "      </" + std::string(section) + ">\n";
}

void write_array(std::string& s, const VtkArray& a, ArraySink& sink) {
  s += "        <DataArray type=\"";
  s += vtk_type_name(a.type);
  s += "\" Name=\"" + a.name + "\" NumberOfComponents=\"" + std::to_string(a.components) + "\"";
  for (std::size_t k = 0; k < a.component_names.size(); ++k) {
    s += " ComponentName" + std::to_string(k) + "=\"" + a.component_names[k] + "\"";
  }
  sink.close_tag(s, sink.ascii() ? std::string() : raw_bytes(a.type, a.values));
  if (!sink.ascii()) return;
  s += "\n";
  const std::size_t width = static_cast<std::size_t>(a.components);
  for (std::size_t i = 0; i + width <= a.values.size(); i += width) {
    s += "         ";
    // Appended piecewise: GCC 12 warns (-Wrestrict, a false positive) on " " + a string.
    for (std::size_t k = 0; k < width; ++k) {
      s += ' ';
      s += text_of(a.type, a.values[i + k]);
    }
    s += "\n";
  }
  s += "        </DataArray>\n";
}

void write_data(std::string& s, const std::vector<VtkArray>& arrays, const char* section,
                const std::string& scalars, ArraySink& sink) {
  if (arrays.empty()) return;
  s += "      <" + std::string(section);
  if (!scalars.empty()) s += " Scalars=\"" + scalars + "\"";
  s += ">\n";
  for (const VtkArray& a : arrays) write_array(s, a, sink);
  s += "      </" + std::string(section) + ">\n";
}

}  // namespace

const VtkArray* VtkPolyData::find_point_array(const std::string& name) const {
  return find_array(point_data, name);
}

const VtkArray* VtkPolyData::find_cell_array(const std::string& name) const {
  return find_array(cell_data, name);
}

std::vector<Vec2> VtkPolyData::polygon(std::size_t i) const {
  if (!polys || i >= polys->size()) {
    throw std::out_of_range("VtkPolyData: no polygon " + std::to_string(i));
  }
  const std::size_t begin = i == 0 ? 0 : static_cast<std::size_t>(polys->offsets[i - 1]);
  const std::size_t end = static_cast<std::size_t>(polys->offsets[i]);
  std::vector<Vec2> out;
  for (std::size_t k = begin; k < end; ++k) {
    out.push_back(points.at(static_cast<std::size_t>(polys->connectivity.at(k))));
  }
  return out;
}

std::string vtk_compressed_array(const std::string& raw, std::size_t block_size) {
  // Full blocks, and a last one holding the rest; its size is 0 in the header when the data
  // fill the last block exactly (vtkXMLDataParser then takes every block as full), and an
  // empty array has no block at all.
  const std::size_t blocks = (raw.size() + block_size - 1) / block_size;
  std::string header, body;
  put_le(header, blocks, 8);
  put_le(header, block_size, 8);
  put_le(header, raw.size() % block_size, 8);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t begin = b * block_size;
    const std::size_t size = std::min(block_size, raw.size() - begin);
    uLongf packed = compressBound(static_cast<uLong>(size));
    std::string out(packed, '\0');
    const int rc = compress2(reinterpret_cast<Bytef*>(out.data()), &packed,
                             reinterpret_cast<const Bytef*>(raw.data() + begin),
                             static_cast<uLong>(size), Z_BEST_SPEED);
    if (rc != Z_OK) throw std::runtime_error("vtk: zlib could not compress an array block");
    put_le(header, packed, 8);
    body.append(out.data(), packed);
  }
  return header + body;
}

std::string vtp_file(const VtkPolyData& p, VtkEncoding encoding) {
  ArraySink sink(encoding);
  std::string s = opening(p, encoding);
  write_points(s, p, sink);
  write_cells(s, p.verts, "Verts", sink);
  write_cells(s, p.lines, "Lines", sink);
  write_cells(s, p.polys, "Polys", sink);
  write_data(s, p.point_data, "PointData", p.point_scalars, sink);
  write_data(s, p.cell_data, "CellData", p.cell_scalars, sink);
  s += "    </Piece>\n  </PolyData>\n";
  if (encoding == VtkEncoding::Binary) {
    s += "  <AppendedData encoding=\"raw\">\n   _";
    s += sink.appended();
    s += "\n  </AppendedData>\n";
  }
  s += "</VTKFile>\n";
  return s;
}

}  // namespace dda
