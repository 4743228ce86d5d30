// Strain tensors in turned frames. One sign convention everywhere (see paper-notes item 1):
// a positive angle is counter-clockwise, as r0 in T.
#pragma once

#include "kinematics/types.hpp"

namespace dda {

// Components [exx, eyy, gxy] (engineering shear) of strain `e`, given in some frame, as seen
// in a frame turned counter-clockwise by `theta` from it:
//   e'x = (ex+ey)/2 + (ex-ey)/2 cos 2t + (gxy/2) sin 2t
//   e'y = (ex+ey)/2 - (ex-ey)/2 cos 2t - (gxy/2) sin 2t
//   g'xy = -(ex-ey) sin 2t + gxy cos 2t
Vec3 strain_in_turned_frame(const Vec3& e, double theta);

}  // namespace dda
