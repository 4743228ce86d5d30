// Colours for pictures: a qualitative palette for categories (materials, block groups) and a
// sequential map for a continuous quantity (displacement, stress).
#pragma once

#include "io/image.hpp"

namespace dda {

// The ten colours of matplotlib's "tab10" palette (Tableau 10), cycling: index 10 is index 0
// again; negative indices cycle too.
Rgb category_colour(int index);

// Matplotlib's "viridis" at t = 0, 1/4, 1/2, 3/4, 1 (perceptually uniform, readable in grey
// and by colour-blind readers), linearly interpolated in RGB between those anchors; t is
// clamped to [0, 1] and NaN gives the t = 0 colour.
Rgb sequential_colour(double t);

}  // namespace dda
