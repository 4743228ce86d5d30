// The world's state as numpy arrays (dda.Simulation's blocks, contacts, energy, monitors,
// bolts): copies, so that they stay as they were when the run goes on. SI units, the
// global frame, block i the scene's blocks[i].
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "solver/scene.hpp"
#include "solver/world.hpp"

namespace dda::python {

// centroid (n, 2) m, translation (n, 2) m, rotation (n,) rad, area (n,) m^2, velocity (n, 6)
// [u0, v0, r0, exx, eyy, gxy rates], stress (n, 3) [sxx, syy, sxy] Pa, strain (n, 3)
// [exx, eyy, gxy], fixed, rigid, excavated (n,) bool, material (n,) index into the scene's
// materials.
pybind11::dict block_arrays(const World& world);

// Block i's vertices now (m, 2), counter-clockwise. Throws IndexError for a bad i.
pybind11::array_t<double> block_vertices(const World& world, long i);

// The contacts of the last step as the contact frames hold them (io/contact_output.hpp):
// position (k, 2), mode (0 open, 1 slide, 2 lock), bonded, joint, normal_force,
// shear_force, slip, gap, normal (k, 2), vertex_block, edge_block.
pybind11::dict contact_arrays(const World& world);

// The energy account (J/m): the scene's energies now and the ledger's running sums.
pybind11::dict energy_terms(const World& world);

// name (list), position, displacement (since the start) and velocity (m, 2) each.
pybind11::dict monitor_arrays(const World& world);

// name (list), force (N/m, tension positive), plastic_extension (m), broken (bool), length (m).
pybind11::dict bolt_arrays(const World& world);

}  // namespace dda::python
