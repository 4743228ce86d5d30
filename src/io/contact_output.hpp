// The contacts of an output step for ParaView and the summary: one VTK point per
// vertex-to-edge contact, at the vertex where it is now, carrying its mode, forces, step slip,
// gap and joint material, so the failure surface of a slope (sliding and opening joints) can
// be seen; and the count of each mode per joint material. Pure functions of the world.
#pragma once

#include <string>
#include <vector>

#include "io/vtk_polydata.hpp"
#include "solver/world.hpp"

namespace dda {

// "vtk/contacts_NNNNNN.vtp" for the output step `step` (beside the blocks' step_NNNNNN.vtp).
std::string contact_frame_name(int step);

// The world's contacts as a VTK piece: points (one vertex cell each) with the
// point data mode (0 open, 1 slide, 2 lock), bonded (0/1), joint (the joint material's index
// in the scene's order, "default" first), normal_force and shear_force (N/m, compression
// positive; shear along the edge's tangent, on the vertex), slip (m, the last step's, along
// the tangent), gap (m, after the last step's increments; > 0 open, < 0 penetrating),
// normal (unit, out of the edge's block) and the two blocks' indices.
VtkPolyData contacts_piece(const World& world);

// The .vtp file of contacts_piece in that encoding (io/vtk_polydata.hpp).
std::string contacts_vtp_text(const World& world, VtkEncoding encoding);

// How many contacts are in each mode, per joint material (index as in Contact::joint).
struct ContactModeCounts {
  int open = 0;
  int slide = 0;
  int lock = 0;
  int bonded = 0;  // of those: bonded (cohesion and tensile strength acting)
};
std::vector<ContactModeCounts> contact_modes_by_joint(const World& world, std::size_t joint_materials);

}  // namespace dda
