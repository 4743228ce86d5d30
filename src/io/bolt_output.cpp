#include "io/bolt_output.hpp"

#include <cstdio>
#include <functional>

#include "io/output.hpp"

namespace dda {
namespace {

// One cell data array of the bolts: `value(i)` gives bolt i's value.
VtkArray bolt_array(const World& w, VtkType type, const char* name,
                    const std::function<double(std::size_t)>& value) {
  VtkArray a{name, type, 1, {}, {}};
  for (std::size_t i = 0; i < w.bolts.size(); ++i) a.values.push_back(value(i));
  return a;
}

}  // namespace

std::string bolt_frame_name(int step) { return vtk_frame_name("bolts", step); }

VtkPolyData bolts_piece(const World& w) {
  VtkPolyData p;
  VtkCells lines;
  lines.index_type = VtkType::Int64;
  for (const BoltEnd& e : w.bolt_ends) p.points.push_back(e.current);
  for (std::size_t k = 0; k < w.bolts.size(); ++k) {
    lines.connectivity.push_back(static_cast<std::int64_t>(2 * k));
    lines.connectivity.push_back(static_cast<std::int64_t>(2 * k + 1));
    lines.offsets.push_back(static_cast<std::int64_t>(2 * k + 2));
  }
  p.lines = std::move(lines);
  p.cell_scalars = "force";
  const auto flag = [](bool on) { return on ? 1.0 : 0.0; };
  std::vector<VtkArray>& cd = p.cell_data;
  cd.push_back(bolt_array(w, VtkType::Int32, "bolt", [](std::size_t i) { return static_cast<double>(i); }));
  cd.push_back(bolt_array(w, VtkType::Float64, "force", [&w](std::size_t i) { return w.bolts[i].force; }));
  cd.push_back(bolt_array(w, VtkType::Float64, "plastic_extension",
                          [&w](std::size_t i) { return w.bolts[i].plastic_extension; }));
  cd.push_back(bolt_array(w, VtkType::Int32, "yielding",
                          [&](std::size_t i) { return flag(bolt_yielding(w.bolts[i])); }));
  cd.push_back(bolt_array(w, VtkType::Int32, "broken", [&](std::size_t i) { return flag(w.bolts[i].broken); }));
  return p;
}

std::string bolts_vtp_text(const World& w, VtkEncoding encoding) {
  return vtp_file(bolts_piece(w), encoding);
}

}  // namespace dda
