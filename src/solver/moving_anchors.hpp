// Displacement control through pins: a RunHook::before_step that moves every pin's anchor
// by a fixed displacement before each step (a platen pushed down, a footing pressed in).
#pragma once

#include <functional>

#include "kinematics/types.hpp"
#include "solver/world.hpp"

namespace dda {

// Moves every pin's anchor by `per_step` (m). The pins' springs then store
// p/2 (|x - a'|^2 - |x - a|^2) more at the points where the step starts: the work of
// whatever moves the anchors, booked as load work so that the energy account (and its
// guard) sees it. Within the step the anchors stay put, as the account assumes.
void move_pin_anchors(World& world, const Vec2& per_step);

// The same as a hook: RunHook{.before_step = moving_anchors(per_step)}.
std::function<void(World&)> moving_anchors(const Vec2& per_step);

}  // namespace dda
