#include "io/contact_output.hpp"

#include <cstdio>
#include <functional>

#include "io/output.hpp"

namespace dda {
namespace {

int mode_code(ContactMode m) {
  switch (m) {
    case ContactMode::Open: return 0;
    case ContactMode::Slide: return 1;
    case ContactMode::Lock: return 2;
  }
  return 0;
}

// One <DataArray> of point data: `value(c)` writes contact c's components.
void point_array(std::string& s, const World& w, const char* type, const char* name, int components,
                 const std::function<std::string(const Contact&)>& value) {
  s += "        <DataArray type=\"";
  s += type;
  s += "\" Name=\"";
  s += name;
  s += "\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"ascii\">\n";
  for (const Contact& c : w.contacts) s += "          " + value(c) + "\n";
  s += "        </DataArray>\n";
}

std::string num(double x) { return format_full_precision(x); }

}  // namespace

std::string contact_frame_name(int step) { return vtk_frame_name("contacts", step); }

std::string contacts_vtp_text(const World& w) {
  const std::size_t n = w.contacts.size();
  std::string s = vtp_opening(n, n, 0, 0);
  s += "      <Points>\n";
  s += "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Contact& c : w.contacts) {
    const Vec2& p = w.blocks[static_cast<std::size_t>(c.key.vertex_block)]
                        .vertices[static_cast<std::size_t>(c.key.vertex)];
    s += "          " + num(p.x()) + " " + num(p.y()) + " 0\n";
  }
  s += "        </DataArray>\n      </Points>\n      <Verts>\n";
  std::string connectivity, offsets;
  for (std::size_t k = 0; k < n; ++k) {
    connectivity += ' ';
    connectivity += std::to_string(k);
    offsets += ' ';
    offsets += std::to_string(k + 1);
  }
  s += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" + connectivity +
       "</DataArray>\n";
  s += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" + offsets +
       "</DataArray>\n";
  s += "      </Verts>\n      <PointData Scalars=\"mode\">\n";
  point_array(s, w, "Int32", "mode", 1, [](const Contact& c) { return std::to_string(mode_code(c.state.mode)); });
  point_array(s, w, "Int32", "bonded", 1, [](const Contact& c) { return std::string(c.state.bonded ? "1" : "0"); });
  point_array(s, w, "Int32", "joint", 1, [](const Contact& c) { return std::to_string(c.joint); });
  point_array(s, w, "Float64", "normal_force", 1, [](const Contact& c) { return num(c.state.normal_force); });
  point_array(s, w, "Float64", "shear_force", 1, [](const Contact& c) { return num(c.iterate.shear_force); });
  point_array(s, w, "Float64", "slip", 1, [](const Contact& c) { return num(c.iterate.slip); });
  point_array(s, w, "Float64", "gap", 1, [](const Contact& c) { return num(c.iterate.new_gap); });
  point_array(s, w, "Float64", "normal", 3, [](const Contact& c) {
    return num(c.normal.x()) + " " + num(c.normal.y()) + " 0";
  });
  point_array(s, w, "Int32", "vertex_block", 1, [](const Contact& c) { return std::to_string(c.key.vertex_block); });
  point_array(s, w, "Int32", "edge_block", 1, [](const Contact& c) { return std::to_string(c.key.edge_block); });
  s += "      </PointData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return s;
}

std::vector<ContactModeCounts> contact_modes_by_joint(const World& world, std::size_t joint_materials) {
  std::vector<ContactModeCounts> out(joint_materials);
  for (const Contact& c : world.contacts) {
    if (c.joint < 0 || static_cast<std::size_t>(c.joint) >= out.size()) continue;
    ContactModeCounts& k = out[static_cast<std::size_t>(c.joint)];
    switch (c.state.mode) {
      case ContactMode::Open: ++k.open; break;
      case ContactMode::Slide: ++k.slide; break;
      case ContactMode::Lock: ++k.lock; break;
    }
    if (c.state.bonded) ++k.bonded;
  }
  return out;
}

}  // namespace dda
