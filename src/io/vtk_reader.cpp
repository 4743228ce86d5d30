#include "io/vtk_reader.hpp"

#include <bit>
#include <charconv>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <zlib.h>

namespace dda {
namespace {

// One XML start or end tag of the file's header part.
struct Tag {
  std::string name;
  std::map<std::string, std::string> attributes;
  bool end = false;           // </name>
  bool self_closing = false;  // <name ... />
  std::size_t after = 0;      // the position after '>'
};

// An array as the file holds it, before its values are given their place.
struct RawArray {
  std::string section;  // Points, Verts, Lines, Polys, PointData, CellData
  std::string name;
  VtkType type = VtkType::Float64;
  int components = 1;
  std::vector<std::string> component_names;
  std::vector<double> values;
  bool own_line = false;  // ASCII indices on a line of their own (VtkCells::ascii_own_line)
};

class Reader {
 public:
  Reader(const std::string& bytes, std::string name) : bytes_(bytes), name_(std::move(name)) {}

  VtkPolyData read();

 private:
  const std::string& bytes_;
  std::string name_;
  std::size_t header_end_ = 0;     // where the XML header ends (<AppendedData or the end)
  std::size_t appended_ = 0;       // the byte after AppendedData's "_" (0 when none)
  bool has_appended_ = false;
  bool compressed_ = false;
  int header_bytes_ = 4;           // header_type UInt32 (the default) or UInt64

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("vtk reader: " + name_ + ": " + what);
  }
  bool next_tag(std::size_t& pos, Tag& tag) const;
  void read_file_tag(const Tag& tag);
  void find_appended();
  RawArray read_array(const Tag& tag, const std::string& section);
  std::vector<double> ascii_values(const Tag& tag, VtkType type) const;
  std::vector<double> appended_values(const Tag& tag, VtkType type) const;
  std::string inflate_at(std::size_t offset) const;
  std::uint64_t header_word(std::size_t at) const;
  std::size_t count(const std::map<std::string, std::string>& attributes, const char* key) const;
  void place(VtkPolyData& piece, std::vector<RawArray>& arrays, const Tag& piece_tag) const;
};

std::uint64_t le_bits(const std::string& bytes, std::size_t at, int width) {
  std::uint64_t bits = 0;
  for (int k = 0; k < width; ++k) {
    bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)])) << (8 * k);
  }
  return bits;
}

int word_size(VtkType type) {
  switch (type) {
    case VtkType::Int32: return 4;
    case VtkType::Int64: return 8;
    case VtkType::UInt8: return 1;
    case VtkType::Float64: return 8;
  }
  return 8;
}

double value_from_bits(VtkType type, std::uint64_t bits) {
  switch (type) {
    case VtkType::Int32: return static_cast<std::int32_t>(static_cast<std::uint32_t>(bits));
    case VtkType::Int64: return static_cast<double>(static_cast<std::int64_t>(bits));
    case VtkType::UInt8: return static_cast<double>(bits);
    case VtkType::Float64: return std::bit_cast<double>(bits);
  }
  return 0.0;
}

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

bool Reader::next_tag(std::size_t& pos, Tag& tag) const {
  for (;;) {
    const std::size_t open = bytes_.find('<', pos);
    if (open == std::string::npos || open >= header_end_) return false;
    const std::size_t close = bytes_.find('>', open);
    if (close == std::string::npos || close > header_end_) fail("a tag is not closed");
    pos = close + 1;
    if (bytes_[open + 1] == '?' || bytes_[open + 1] == '!') continue;  // declaration, comment
    tag = Tag{};
    tag.after = pos;
    std::size_t at = open + 1;
    if (bytes_[at] == '/') {
      tag.end = true;
      ++at;
    }
    std::size_t stop = close;
    if (bytes_[close - 1] == '/') {
      tag.self_closing = true;
      --stop;
    }
    while (at < stop && !is_space(bytes_[at])) tag.name += bytes_[at++];
    // Attributes: key="value", separated by white space.
    for (;;) {
      while (at < stop && is_space(bytes_[at])) ++at;
      if (at >= stop) break;
      const std::size_t eq = bytes_.find('=', at);
      if (eq == std::string::npos || eq + 1 >= stop || bytes_[eq + 1] != '"') {
        fail("a malformed attribute in <" + tag.name + ">");
      }
      const std::size_t quote = bytes_.find('"', eq + 2);
      if (quote == std::string::npos || quote >= stop) fail("an unterminated attribute in <" + tag.name + ">");
      tag.attributes[bytes_.substr(at, eq - at)] = bytes_.substr(eq + 2, quote - eq - 2);
      at = quote + 1;
    }
    return true;
  }
}

std::size_t Reader::count(const std::map<std::string, std::string>& attributes, const char* key) const {
  const auto it = attributes.find(key);
  if (it == attributes.end()) return 0;
  std::size_t n = 0;
  const std::string& text = it->second;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), n);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) {
    fail(std::string("attribute ") + key + "=\"" + text + "\" is not a count");
  }
  return n;
}

void Reader::find_appended() {
  header_end_ = bytes_.find("<AppendedData");
  if (header_end_ == std::string::npos) {
    header_end_ = bytes_.size();
    return;
  }
  const std::size_t close = bytes_.find('>', header_end_);
  if (close == std::string::npos) fail("<AppendedData> is not closed");
  const std::string tag = bytes_.substr(header_end_, close - header_end_);
  if (tag.find("encoding=\"raw\"") == std::string::npos) {
    fail("<AppendedData> is not encoding=\"raw\" (base64 is not read)");
  }
  // The data begin after the first "_" (VTK File Formats: "the first character ... is an
  // underscore"); the offsets count from the byte after it.
  const std::size_t underscore = bytes_.find('_', close);
  if (underscore == std::string::npos) fail("<AppendedData> has no \"_\" before its data");
  appended_ = underscore + 1;
  has_appended_ = true;
}

void Reader::read_file_tag(const Tag& tag) {
  const auto attr = [&](const char* key) {
    const auto it = tag.attributes.find(key);
    return it == tag.attributes.end() ? std::string() : it->second;
  };
  if (attr("type") != "PolyData") fail("not a PolyData file (type=\"" + attr("type") + "\")");
  if (attr("byte_order") != "LittleEndian") fail("byte_order is not LittleEndian");
  const std::string header = attr("header_type");
  if (header == "UInt64") {
    header_bytes_ = 8;
  } else if (!header.empty() && header != "UInt32") {
    fail("header_type \"" + header + "\" is neither UInt32 nor UInt64");
  }
  const std::string compressor = attr("compressor");
  if (compressor == "vtkZLibDataCompressor") {
    compressed_ = true;
  } else if (!compressor.empty()) {
    fail("compressor \"" + compressor + "\" is not vtkZLibDataCompressor");
  }
}

std::vector<double> Reader::ascii_values(const Tag& tag, VtkType type) const {
  const std::size_t end = bytes_.find("</DataArray>", tag.after);
  if (end == std::string::npos || end > header_end_) fail("a DataArray is not closed");
  std::vector<double> out;
  const char* p = bytes_.data() + tag.after;
  const char* stop = bytes_.data() + end;
  while (p < stop) {
    if (is_space(*p)) {
      ++p;
      continue;
    }
    double v = 0.0;
    std::from_chars_result r{};
    if (type == VtkType::Float64) {
      r = std::from_chars(p, stop, v);
    } else {
      long long n = 0;
      r = std::from_chars(p, stop, n);
      v = static_cast<double>(n);
    }
    if (r.ec != std::errc() || (r.ptr < stop && !is_space(*r.ptr))) {
      const char* word_end = p;
      while (word_end < stop && !is_space(*word_end)) ++word_end;
      // Built by appending: GCC 12 warns falsely (-Wrestrict) on "\"" + std::string(...).
      std::string what = "\"";
      what.append(p, word_end);
      what += "\" in array \"" + tag.attributes.at("Name") + "\" is not a " + vtk_type_name(type);
      fail(what);
    }
    out.push_back(v);
    p = r.ptr;
  }
  return out;
}

std::uint64_t Reader::header_word(std::size_t at) const {
  if (at + static_cast<std::size_t>(header_bytes_) > bytes_.size()) {
    fail("appended data end inside an array's header");
  }
  return le_bits(bytes_, at, header_bytes_);
}

// The array's bytes at `offset` in the appended section: VTK's compressed layout (header
// [blocks, block size, last partial block size or 0, compressed sizes...], then the blocks),
// or without a compressor the byte count and the bytes.
std::string Reader::inflate_at(std::size_t offset) const {
  const std::size_t start = appended_ + offset;
  if (offset > bytes_.size() || start > bytes_.size()) fail("an array's offset is past the end");
  const std::size_t word = static_cast<std::size_t>(header_bytes_);
  if (!compressed_) {
    const std::uint64_t size = header_word(start);
    if (size > bytes_.size() - start - word) fail("an array runs past the end of the file");
    return bytes_.substr(start + word, size);
  }
  const std::uint64_t blocks = header_word(start);
  const std::uint64_t block_size = header_word(start + word);
  const std::uint64_t last = header_word(start + 2 * word);
  if (blocks > (bytes_.size() - start) / word) fail("an array's header declares too many blocks");
  // A block larger than 1 GiB is no file of ours; the bound keeps a bad header from
  // asking for absurd memory.
  if (blocks > 0 && (block_size == 0 || block_size > (std::uint64_t{1} << 30) || last >= block_size)) {
    fail("an array's header has a bad block size");
  }
  std::size_t data = start + 3 * word + blocks * word;
  std::string out;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t packed = header_word(start + (3 + b) * word);
    if (data > bytes_.size() || packed > bytes_.size() - data) fail("a compressed block runs past the end");
    // Every block is full but the last, which is `last` bytes when that is not 0.
    const std::uint64_t size = (b + 1 == blocks && last != 0) ? last : block_size;
    std::string block(size, '\0');
    uLongf got = static_cast<uLongf>(size);
    const int rc = uncompress(reinterpret_cast<Bytef*>(block.data()), &got,
                              reinterpret_cast<const Bytef*>(bytes_.data() + data), static_cast<uLong>(packed));
    if (rc != Z_OK || got != size) {
      fail("compressed block " + std::to_string(b) + " does not inflate to its " +
           std::to_string(size) + " bytes (zlib: " + std::to_string(rc) + ")");
    }
    out += block;
    data += packed;
  }
  return out;
}

std::vector<double> Reader::appended_values(const Tag& tag, VtkType type) const {
  if (!has_appended_) fail("an appended array but no <AppendedData>");
  const auto it = tag.attributes.find("offset");
  if (it == tag.attributes.end()) fail("an appended array without an offset");
  const std::string raw = inflate_at(count(tag.attributes, "offset"));
  const std::size_t width = static_cast<std::size_t>(word_size(type));
  if (raw.size() % width != 0) fail("an array's byte count is not a whole number of values");
  std::vector<double> out(raw.size() / width);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = value_from_bits(type, le_bits(raw, i * width, static_cast<int>(width)));
  }
  return out;
}

RawArray Reader::read_array(const Tag& tag, const std::string& section) {
  if (section.empty()) fail("a DataArray outside Points, Verts, Lines, Polys, PointData, CellData");
  RawArray a;
  a.section = section;
  const auto attr = [&](const char* key) {
    const auto it = tag.attributes.find(key);
    return it == tag.attributes.end() ? std::string() : it->second;
  };
  a.name = attr("Name");
  const std::string type = attr("type");
  bool known = false;
  for (VtkType t : {VtkType::Int32, VtkType::Int64, VtkType::UInt8, VtkType::Float64}) {
    if (type == vtk_type_name(t)) {
      a.type = t;
      known = true;
    }
  }
  if (!known) fail("array \"" + a.name + "\" has type \"" + type + "\", not one this code writes");
  if (tag.attributes.count("NumberOfComponents")) {
    const std::size_t n = count(tag.attributes, "NumberOfComponents");
    if (n < 1 || n > 9) fail("array \"" + a.name + "\" has " + std::to_string(n) + " components");
    a.components = static_cast<int>(n);
  }
  for (int k = 0; k < a.components; ++k) {
    const std::string name = attr(("ComponentName" + std::to_string(k)).c_str());
    if (!name.empty()) a.component_names.resize(static_cast<std::size_t>(a.components));
    if (!name.empty()) a.component_names[static_cast<std::size_t>(k)] = name;
  }
  const std::string format = attr("format");
  if (format == "ascii") {
    a.values = ascii_values(tag, a.type);
    a.own_line = tag.after < bytes_.size() && bytes_[tag.after] == '\n';
  } else if (format == "appended") {
    a.values = appended_values(tag, a.type);
  } else {
    fail("array \"" + a.name + "\" has format \"" + format + "\" (ascii or appended are read)");
  }
  return a;
}

void Reader::place(VtkPolyData& piece, std::vector<RawArray>& arrays, const Tag& piece_tag) const {
  const std::size_t points = count(piece_tag.attributes, "NumberOfPoints");
  if (count(piece_tag.attributes, "NumberOfStrips") != 0) fail("strips are not read");
  bool have_points = false;
  for (RawArray& a : arrays) {
    if (a.section == "Points") {
      if (a.components != 3 || a.values.size() != 3 * points) {
        fail("the points array holds " + std::to_string(a.values.size()) + " numbers, not 3 x " +
             std::to_string(points));
      }
      for (std::size_t i = 0; i < points; ++i) piece.points.emplace_back(a.values[3 * i], a.values[3 * i + 1]);
      have_points = true;
    }
  }
  if (!have_points && points > 0) fail("no points array");
  for (const char* section : {"Verts", "Lines", "Polys"}) {
    std::optional<VtkCells>& cells = std::string(section) == "Verts"   ? piece.verts
                                     : std::string(section) == "Lines" ? piece.lines
                                                                       : piece.polys;
    const std::size_t declared = count(piece_tag.attributes, ("NumberOf" + std::string(section)).c_str());
    const RawArray* connectivity = nullptr;
    const RawArray* offsets = nullptr;
    for (const RawArray& a : arrays) {
      if (a.section != section) continue;
      if (a.name == "connectivity") connectivity = &a;
      if (a.name == "offsets") offsets = &a;
    }
    if (!connectivity && !offsets) {
      if (declared != 0) fail(std::string("the piece declares ") + section + " but has none");
      continue;
    }
    if (!connectivity || !offsets) fail(std::string(section) + " lack connectivity or offsets");
    if (connectivity->type == VtkType::Float64 || offsets->type == VtkType::Float64) {
      fail(std::string(section) + "' indices are not integers");
    }
    if (offsets->values.size() != declared) {
      fail(std::string(section) + " have " + std::to_string(offsets->values.size()) +
           " offsets for " + std::to_string(declared) + " cells");
    }
    VtkCells c;
    c.index_type = connectivity->type;
    c.ascii_own_line = connectivity->own_line;
    double previous = 0.0;
    for (double v : offsets->values) {
      if (v < previous) fail(std::string(section) + "' offsets decrease");
      previous = v;
      c.offsets.push_back(static_cast<std::int64_t>(v));
    }
    if (static_cast<double>(connectivity->values.size()) != previous) {
      fail(std::string(section) + "' connectivity holds " + std::to_string(connectivity->values.size()) +
           " indices, the offsets " + std::to_string(static_cast<long long>(previous)));
    }
    for (double v : connectivity->values) {
      if (v < 0 || v >= static_cast<double>(points)) {
        fail(std::string(section) + " use point " + std::to_string(static_cast<long long>(v)) +
             " of " + std::to_string(points));
      }
      c.connectivity.push_back(static_cast<std::int64_t>(v));
    }
    cells = std::move(c);
  }
  for (RawArray& a : arrays) {
    if (a.section != "PointData" && a.section != "CellData") continue;
    const bool point = a.section == "PointData";
    const std::size_t tuples = point ? points : piece.cells();
    if (a.values.size() != tuples * static_cast<std::size_t>(a.components)) {
      fail("array \"" + a.name + "\" holds " + std::to_string(a.values.size()) + " numbers, not " +
           std::to_string(tuples) + " x " + std::to_string(a.components));
    }
    VtkArray out{a.name, a.type, a.components, a.component_names, std::move(a.values)};
    (point ? piece.point_data : piece.cell_data).push_back(std::move(out));
  }
}

VtkPolyData Reader::read() {
  find_appended();
  std::size_t pos = 0;
  Tag tag;
  bool file_seen = false;
  std::optional<Tag> piece_tag;
  std::string section;
  std::vector<RawArray> arrays;
  VtkPolyData piece;
  while (next_tag(pos, tag)) {
    if (tag.name == "VTKFile" && !tag.end) {
      read_file_tag(tag);
      file_seen = true;
    } else if (tag.name == "Piece" && !tag.end) {
      if (piece_tag) fail("more than one piece");
      piece_tag = tag;
    } else if (tag.name == "Points" || tag.name == "Verts" || tag.name == "Lines" ||
               tag.name == "Polys" || tag.name == "PointData" || tag.name == "CellData") {
      if (!piece_tag) fail("<" + tag.name + "> outside a piece");
      section = tag.end ? std::string() : tag.name;
      if (!tag.end && tag.name == "PointData" && tag.attributes.count("Scalars")) piece.point_scalars = tag.attributes.at("Scalars");
      if (!tag.end && tag.name == "CellData" && tag.attributes.count("Scalars")) piece.cell_scalars = tag.attributes.at("Scalars");
    } else if (tag.name == "DataArray" && !tag.end) {
      arrays.push_back(read_array(tag, section));
    } else if (tag.name == "Strips" && !tag.end) {
      fail("strips are not read");
    }
  }
  if (!file_seen) fail("no <VTKFile> element");
  if (!piece_tag) fail("no <Piece> element");
  place(piece, arrays, *piece_tag);
  return piece;
}

}  // namespace

VtkPolyData parse_vtp(const std::string& bytes, const std::string& name) {
  return Reader(bytes, name).read();
}

VtkPolyData read_vtp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("vtk reader: cannot open " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw std::runtime_error("vtk reader: cannot read " + path.string());
  return parse_vtp(text.str(), path.string());
}

}  // namespace dda
