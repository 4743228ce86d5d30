// The bolts' VTK series (docs/output-format.md, "vtk/bolts_NNNNNN.vtp"): each bolt a line
// between its two ends, with its force, yield and rupture as cell data, for ParaView beside
// the blocks and the contacts. Written only for a scene with bolts.
#pragma once

#include <string>

#include "solver/world.hpp"

namespace dda {

// "vtk/bolts_000120.vtp" for step 120.
std::string bolt_frame_name(int step);

// The bolts of `world` as VTK PolyData lines.
std::string bolts_vtp_text(const World& world);

}  // namespace dda
