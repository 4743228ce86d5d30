#include "python/world_arrays.hpp"

#include <string>
#include <vector>

#include "io/contact_output.hpp"
#include "io/output.hpp"
#include "solver/energy.hpp"

namespace py = pybind11;

namespace dda::python {
namespace {

// An (n, width) array of doubles filled row by row by `row(i, out)`.
template <class Fill>
py::array_t<double> rows(std::size_t n, std::size_t width, Fill row) {
  py::array_t<double> a({n, width});
  auto m = a.mutable_unchecked<2>();
  std::vector<double> values(width);
  for (std::size_t i = 0; i < n; ++i) {
    row(i, values.data());
    for (std::size_t k = 0; k < width; ++k) m(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(k)) = values[k];
  }
  return a;
}

// An (n,) array of T with `value(i)`.
template <class T, class Value>
py::array_t<T> column(std::size_t n, Value value) {
  py::array_t<T> a(static_cast<py::ssize_t>(n));
  auto m = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < n; ++i) m(static_cast<py::ssize_t>(i)) = static_cast<T>(value(i));
  return a;
}

}  // namespace

py::dict block_arrays(const World& world) {
  const auto& b = world.blocks;
  const std::size_t n = b.size();
  py::dict d;
  d["centroid"] = rows(n, 2, [&](std::size_t i, double* o) {
    o[0] = b[i].moments.centroid.x();
    o[1] = b[i].moments.centroid.y();
  });
  d["translation"] = rows(n, 2, [&](std::size_t i, double* o) {
    o[0] = b[i].translation.x();
    o[1] = b[i].translation.y();
  });
  d["rotation"] = column<double>(n, [&](std::size_t i) { return b[i].rotation; });
  d["area"] = column<double>(n, [&](std::size_t i) { return b[i].moments.area; });
  d["velocity"] = rows(n, 6, [&](std::size_t i, double* o) {
    for (int k = 0; k < 6; ++k) o[k] = b[i].velocity[k];
  });
  d["stress"] = rows(n, 3, [&](std::size_t i, double* o) {
    for (int k = 0; k < 3; ++k) o[k] = b[i].stress[k];
  });
  d["strain"] = rows(n, 3, [&](std::size_t i, double* o) {
    for (int k = 0; k < 3; ++k) o[k] = b[i].strain[k];
  });
  d["fixed"] = column<bool>(n, [&](std::size_t i) { return b[i].fixed; });
  d["rigid"] = column<bool>(n, [&](std::size_t i) { return b[i].rigid; });
  d["excavated"] = column<bool>(n, [&](std::size_t i) { return b[i].excavated; });
  d["material"] = column<long>(n, [&](std::size_t i) { return b[i].material; });
  return d;
}

py::array_t<double> block_vertices(const World& world, long i) {
  const long n = static_cast<long>(world.blocks.size());
  if (i < 0) i += n;
  if (i < 0 || i >= n) throw py::index_error("block index out of range (" + std::to_string(n) + " blocks)");
  const Polygon& v = world.blocks[static_cast<std::size_t>(i)].vertices;
  return rows(v.size(), 2, [&](std::size_t k, double* o) {
    o[0] = v[k].x();
    o[1] = v[k].y();
  });
}

py::dict contact_arrays(const World& world) {
  const VtkPolyData piece = contacts_piece(world);
  const std::size_t n = piece.points.size();
  py::dict d;
  d["position"] = rows(n, 2, [&](std::size_t i, double* o) {
    o[0] = piece.points[i].x();
    o[1] = piece.points[i].y();
  });
  for (const VtkArray& a : piece.point_data) {
    if (a.components == 1 && a.type != VtkType::Float64) {
      d[py::str(a.name)] = column<long>(n, [&](std::size_t i) { return a.at(i); });
    } else if (a.components == 1) {
      d[py::str(a.name)] = column<double>(n, [&](std::size_t i) { return a.at(i); });
    } else {
      // The frames' vectors carry z = 0 for VTK; the plane's two components here.
      const std::size_t width = a.components == 3 ? 2 : static_cast<std::size_t>(a.components);
      d[py::str(a.name)] = rows(n, width, [&](std::size_t i, double* o) {
        for (std::size_t k = 0; k < width; ++k) o[k] = a.at(i, static_cast<int>(k));
      });
    }
  }
  return d;
}

py::dict energy_terms(const World& world) {
  const EnergyTotals now = scene_energy(world);
  const EnergyLedger& led = world.energy;
  py::dict d;
  d["kinetic"] = now.kinetic;
  d["potential"] = now.potential;
  d["strain_energy"] = now.strain_energy;
  d["contact_energy"] = now.contact_energy;
  d["total"] = now.total();
  d["initial_total"] = led.initial_total;
  d["load_work"] = led.load_work;
  d["multiplier_work"] = led.multiplier_work;
  d["friction_dissipation"] = led.friction_dissipation;
  d["plastic_dissipation"] = led.plastic_dissipation;
  d["damping_dissipation"] = led.damping_dissipation;
  d["friction_gain"] = led.friction_gain;
  d["excavation"] = led.excavation;
  d["remainder"] = led.remainder;
  d["remainder_max"] = led.remainder_max;
  d["remainder_min"] = led.remainder_min;
  d["scale"] = led.scale;
  return d;
}

py::dict monitor_arrays(const World& world) {
  const auto& m = world.monitors;
  const std::size_t n = m.size();
  py::list names;
  for (const Monitor& x : m) names.append(x.name);
  py::dict d;
  d["name"] = names;
  d["position"] = rows(n, 2, [&](std::size_t i, double* o) {
    o[0] = m[i].current.x();
    o[1] = m[i].current.y();
  });
  d["displacement"] = rows(n, 2, [&](std::size_t i, double* o) {
    const Vec2 u = m[i].current - m[i].initial;
    o[0] = u.x();
    o[1] = u.y();
  });
  d["velocity"] = rows(n, 2, [&](std::size_t i, double* o) {
    const Vec2 v = monitor_velocity(world, m[i]);
    o[0] = v.x();
    o[1] = v.y();
  });
  return d;
}

py::dict bolt_arrays(const World& world) {
  const auto& b = world.bolts;
  const std::size_t n = b.size();
  py::list names;
  for (const Bolt& x : b) names.append(x.name);
  py::dict d;
  d["name"] = names;
  d["force"] = column<double>(n, [&](std::size_t i) { return b[i].force; });
  d["plastic_extension"] = column<double>(n, [&](std::size_t i) { return b[i].plastic_extension; });
  d["broken"] = column<bool>(n, [&](std::size_t i) { return b[i].broken; });
  d["length"] = column<double>(n, [&](std::size_t i) {
    return (world.bolt_ends[2 * i + 1].current - world.bolt_ends[2 * i].current).norm();
  });
  return d;
}

}  // namespace dda::python
