// Plasticity in a boundary-value problem: a rigid, smooth strip footing
// pressed into a weightless layer of Tresca (Mohr-Coulomb, phi = 0) blocks, against
// Prandtl's bearing capacity q_u = (2 + pi) c. The layer is a mesh of constant-strain
// triangular blocks bonded by joints far stronger than the soil, so the plasticity is in the
// blocks; the footing is a rigid block held by two pins whose anchors the driver moves down
// a fixed distance each static step (displacement control, as
// tests/solver/test_material_coupling.cpp does with its platen). The case library is shared by dda_verify_footing and
// tests/verification/test_footing.cpp.
#pragma once

#include <string>
#include <vector>

#include "kinematics/polygon.hpp"
#include "solver/scene.hpp"

namespace dda::footing {

// How each square cell of the layer is cut into blocks.
enum class Mesh {
  Crossed,  // both diagonals: 4 triangles a cell (Nagtegaal, Parks and Rice's remedy for
            // constant-strain locking under isochoric flow)
  Diagonal, // one diagonal: 2 triangles a cell, the diagonal's direction alternating cell
            // by cell (a chequer, the "union jack" pattern)
  Uniform,  // one diagonal: 2 triangles a cell, every diagonal the same way (/)
};

const char* mesh_name(Mesh m);

struct FootingCase {
  // Soil: Tresca through Mohr-Coulomb with phi = 0 (associated: psi = phi = 0).
  double cohesion = 1e5;        // Pa
  double friction_angle = 0.0;  // degrees
  double young = 1e8;           // Pa: E / c = 1000
  double poisson = 0.3;
  double density = 20.0;        // kg/m^3: only the static step's relaxation term 2 M / dt^2
  // Geometry (half model, symmetric about x = 0): the footing covers [0, b] on the surface
  // y = 0 of the layer [0, length] x [-depth, 0]; Prandtl's mechanism for B = 2 b reaches
  // x = 3 b at the surface and b sqrt 2 deep, inside the layer.
  double half_width = 1.0;  // b (m)
  double length = 4.0;      // m
  double depth = 2.0;       // m
  double cell = 0.5;        // square cell side h (m); b, length and depth must be multiples
  Mesh mesh = Mesh::Crossed;
  // Loading: the footing is pushed down by `settlement` in `steps` equal static steps.
  double settlement = 0.06;  // m
  int steps = 150;
  double time_step = 0.01;   // s
  double max_displacement_ratio = 0.05;
  double penalty_factor = 50.0;  // penalty = this x E (50: the "auto" penalty)
  // control.rotation_update by its scene name; empty: the scene default (finite_rotation_polar).
  std::string rotation_update;
  std::string label() const;  // e.g. "crossed_h0.5_n150"
};

// The scene: blocks (fixed walls, the layer, the rigid footing last), materials, joints,
// two pins on the footing. Block indices: 0 symmetry wall (smooth), 1 base, 2 far wall,
// then the layer, the footing last.
Scene footing_scene(const FootingCase& c);

// Prandtl's bearing pressure of a smooth strip footing on weightless Mohr-Coulomb soil:
// (2 + pi) c for phi = 0, c (N_q - 1) cot phi with N_q = exp(pi tan phi) tan^2(45 + phi/2)
// otherwise.
double prandtl_pressure(double cohesion, double friction_angle_deg);

struct CurvePoint {
  int step = 0;
  double settlement = 0.0;  // m, the footing's downward displacement
  double pressure = 0.0;    // Pa, the pins' force on the footing / b
  int yielding = 0;         // blocks whose last return was plastic
  // Contacts between two layer blocks that share an edge (the bonds that hold the mesh
  // together), by mode, and those of them no longer bonded: anything but locked and bonded
  // means the mesh gave way there. And the closed contacts of blocks meeting at a corner only.
  int edge_locked = 0, edge_sliding = 0, edge_open = 0, edge_unbonded = 0;
  int corner_closed = 0;
  long solves = 0;          // linear solves of the step (cut attempts included)
  int cuts = 0;             // attempts of the step thrown away
  std::string cut_reasons;  // by reason: d displacement, o open-close, p penetration,
                            // m material, v overshoot (e.g. "o3m1"); empty without cuts
  double energy_remainder = 0.0;  // the energy account's unexplained remainder (J/m)
  double dt = 0.0;          // the step's accepted time step (s)
};

struct PlasticZone {  // the layer at the end: each block's outline and plastic strain
  std::vector<Polygon> polygons;
  std::vector<double> eps_p;
};

struct FootingResult {
  bool ok = true;
  std::string message;   // why the run stopped, when it did
  int blocks = 0;        // blocks of the layer
  std::vector<CurvePoint> curve;
  double final_pressure = 0.0;   // Pa, at the full settlement: the DDA limit pressure
  double wall_s = 0.0;
  double cpu_s = 0.0;    // CPU time of the thread that ran it
  int cut_steps = 0;
  long solves = 0;
  int open_close_max = 0;
  double energy_remainder_max = 0.0;
  double energy_scale = 0.0;
  PlasticZone zone;
};

FootingResult run_footing(const FootingCase& c);

}  // namespace dda::footing
