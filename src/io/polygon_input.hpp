// A polygon read from input (a block's vertices, a cutting model's domain or region): at
// least three [x, y] vertices, no repeated vertex, not all on one line, simple, of non-zero
// area and counter-clockwise. Shared by the scene reader and the model reader so that both
// accept and reject exactly the same polygons, with the same messages at the given place.
#pragma once

#include "io/json_input.hpp"
#include "kinematics/types.hpp"

namespace dda::input {

// Checks the rules above for `poly`; a failure is reported at `f`. Throws InputError.
void check_polygon_shape(const Field& f, const Polygon& poly);

// The list of [x, y] vertices at `f`, checked by check_polygon_shape. Throws InputError.
Polygon read_polygon(const Field& f);

}  // namespace dda::input
