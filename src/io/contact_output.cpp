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

// One point data array of the contacts: `value(c)` gives contact c's components.
VtkArray point_array(const World& w, VtkType type, const char* name, int components,
                     const std::function<std::vector<double>(const Contact&)>& value) {
  VtkArray a{name, type, components, {}, {}};
  for (const Contact& c : w.contacts) {
    for (double v : value(c)) a.values.push_back(v);
  }
  return a;
}

std::vector<double> one(double x) { return {x}; }

}  // namespace

std::string contact_frame_name(int step) { return vtk_frame_name("contacts", step); }

VtkPolyData contacts_piece(const World& w) {
  VtkPolyData p;
  VtkCells verts;
  verts.index_type = VtkType::Int64;
  for (const Contact& c : w.contacts) {
    verts.connectivity.push_back(static_cast<std::int64_t>(p.points.size()));
    p.points.push_back(w.blocks[static_cast<std::size_t>(c.key.vertex_block)]
                           .vertices[static_cast<std::size_t>(c.key.vertex)]);
    verts.offsets.push_back(static_cast<std::int64_t>(p.points.size()));
  }
  p.verts = std::move(verts);
  p.point_scalars = "mode";
  std::vector<VtkArray>& pd = p.point_data;
  pd.push_back(point_array(w, VtkType::Int32, "mode", 1, [](const Contact& c) { return one(mode_code(c.state.mode)); }));
  pd.push_back(point_array(w, VtkType::Int32, "bonded", 1, [](const Contact& c) { return one(c.state.bonded ? 1 : 0); }));
  pd.push_back(point_array(w, VtkType::Int32, "joint", 1, [](const Contact& c) { return one(c.joint); }));
  pd.push_back(point_array(w, VtkType::Float64, "normal_force", 1, [](const Contact& c) { return one(c.state.normal_force); }));
  pd.push_back(point_array(w, VtkType::Float64, "shear_force", 1, [](const Contact& c) { return one(c.iterate.shear_force); }));
  pd.push_back(point_array(w, VtkType::Float64, "slip", 1, [](const Contact& c) { return one(c.iterate.slip); }));
  pd.push_back(point_array(w, VtkType::Float64, "gap", 1, [](const Contact& c) { return one(c.iterate.new_gap); }));
  pd.push_back(point_array(w, VtkType::Float64, "normal", 3, [](const Contact& c) {
    return std::vector<double>{c.normal.x(), c.normal.y(), 0.0};
  }));
  pd.push_back(point_array(w, VtkType::Int32, "vertex_block", 1, [](const Contact& c) { return one(c.key.vertex_block); }));
  pd.push_back(point_array(w, VtkType::Int32, "edge_block", 1, [](const Contact& c) { return one(c.key.edge_block); }));
  return p;
}

std::string contacts_vtp_text(const World& w, VtkEncoding encoding) {
  return vtp_file(contacts_piece(w), encoding);
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
