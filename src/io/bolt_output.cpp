#include "io/bolt_output.hpp"

#include <cstdio>
#include <functional>

#include "io/output.hpp"

namespace dda {
namespace {

std::string num(double x) { return format_full_precision(x); }

// One <DataArray> of cell data: `value(i)` writes bolt i's value.
void cell_array(std::string& s, const World& w, const char* type, const char* name,
                const std::function<std::string(std::size_t)>& value) {
  s += "        <DataArray type=\"";
  s += type;
  s += "\" Name=\"";
  s += name;
  s += "\" NumberOfComponents=\"1\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < w.bolts.size(); ++i) s += "          " + value(i) + "\n";
  s += "        </DataArray>\n";
}

}  // namespace

std::string bolt_frame_name(int step) { return vtk_frame_name("bolts", step); }

std::string bolts_vtp_text(const World& w) {
  const std::size_t n = w.bolts.size();
  std::string s = vtp_opening(2 * n, 0, n, 0);
  s += "      <Points>\n";
  s += "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const BoltEnd& e : w.bolt_ends) {
    s += "          " + num(e.current.x()) + " " + num(e.current.y()) + " 0\n";
  }
  s += "        </DataArray>\n      </Points>\n      <Lines>\n";
  std::string connectivity, offsets;
  for (std::size_t k = 0; k < n; ++k) {
    connectivity += ' ';
    connectivity += std::to_string(2 * k);
    connectivity += ' ';
    connectivity += std::to_string(2 * k + 1);
    offsets += ' ';
    offsets += std::to_string(2 * k + 2);
  }
  s += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" + connectivity +
       "</DataArray>\n";
  s += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" + offsets +
       "</DataArray>\n";
  s += "      </Lines>\n      <CellData Scalars=\"force\">\n";
  cell_array(s, w, "Int32", "bolt", [](std::size_t i) { return std::to_string(i); });
  cell_array(s, w, "Float64", "force", [&w](std::size_t i) { return num(w.bolts[i].force); });
  cell_array(s, w, "Float64", "plastic_extension",
             [&w](std::size_t i) { return num(w.bolts[i].plastic_extension); });
  cell_array(s, w, "Int32", "yielding",
             [&w](std::size_t i) { return std::string(bolt_yielding(w.bolts[i]) ? "1" : "0"); });
  cell_array(s, w, "Int32", "broken", [&w](std::size_t i) { return std::string(w.bolts[i].broken ? "1" : "0"); });
  s += "      </CellData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return s;
}

}  // namespace dda
