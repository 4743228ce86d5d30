// Strain and stress tensors in turned frames. One sign convention everywhere (see
// docs/paper-errata.md, item 1): a positive angle is counter-clockwise, as r0 in T. A block's frame
// (paper Section 3, Fig. 1) is the global frame turned by the block's total rotation.
#pragma once

#include "kinematics/types.hpp"

namespace dda {

// Components [exx, eyy, gxy] (engineering shear) of strain `e`, given in some frame, as seen
// in a frame turned counter-clockwise by `theta` from it:
//   e'x = (ex+ey)/2 + (ex-ey)/2 cos 2t + (gxy/2) sin 2t
//   e'y = (ex+ey)/2 - (ex-ey)/2 cos 2t - (gxy/2) sin 2t
//   g'xy = -(ex-ey) sin 2t + gxy cos 2t
// This is the paper's Eq. (17) with the sign of the angle corrected (printed: theta = -r0).
Vec3 strain_in_turned_frame(const Vec3& e, double theta);

// The inverse: components in the original frame of a strain `e_turned` given in the frame
// turned by `theta` (the paper's Eq. 18, global strain from local strain, with the sign of
// the angle corrected). strain_in_turned_frame(e, -theta).
Vec3 strain_from_turned_frame(const Vec3& e_turned, double theta);

// The same two maps for a stress [sxx, syy, sxy] (tensor shear, not engineering).
Vec3 stress_in_turned_frame(const Vec3& s, double theta);
Vec3 stress_from_turned_frame(const Vec3& s_turned, double theta);

}  // namespace dda
