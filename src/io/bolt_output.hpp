// The bolts' VTK series (docs/output-format.md, "vtk/bolts_NNNNNN.vtp"): each bolt a line
// between its two ends, with its force, yield and rupture as cell data, for ParaView beside
// the blocks and the contacts. Written only for a scene with bolts.
#pragma once

#include <string>

#include "io/vtk_polydata.hpp"
#include "solver/world.hpp"

namespace dda {

// "vtk/bolts_000120.vtp" for step 120.
std::string bolt_frame_name(int step);

// The bolts of `world` as a VTK piece: 2 points per bolt (its ends, in order), one line
// cell each, with cell data bolt, force, plastic_extension, yielding and broken.
VtkPolyData bolts_piece(const World& world);

// The .vtp file of bolts_piece in that encoding (io/vtk_polydata.hpp).
std::string bolts_vtp_text(const World& world, VtkEncoding encoding);

}  // namespace dda
