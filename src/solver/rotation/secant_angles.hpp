// finite_rotation's outer iteration: each block's secant angle r* (the angle inside T's
// rotation column) follows the step's own r0 until the two agree within a tolerance.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "contact/contact.hpp"
#include "kinematics/rotating_inertia.hpp"
#include "solver/world.hpp"

namespace dda {

// finite_rotation iterates each block's secant angle r* to the step's own r0. A secant
// column at r* instead of r0 moves a point at distance l from the reference point by about
// l |r0| |r0 - r*| / 2 off the exact rotation (the column's derivative at small angles is
// -I/2): the iteration stops when that is below this share of w0 for every block, e.g.
// 1e-12 x 5 m per step on the paper's swinging octagon (5e-9 m over its 5000 steps). A
// block that barely turns is done after one solve.
inline constexpr double kSecantDisplacementShare = 1e-12;
// A block in closed contact needs its secant no closer than this share of its contacts'
// smallest allowed penetration: the step's contact equations hold each contact's normal
// and edge fixed over the step, which puts a vertex of a block turning by r0 off by about
// l r0^2 / 2 already, the same order as the secant's own error when its angle is off by r0.
// In a settled pile whose blocks rattle (their r0 changing sign from step to step) the
// strict tolerance cost one more solve a step, for errors of 1e-15 to 5e-8 m (box150:
// median 4e-15, 99.9 % below 2.2e-9, allowance 5e-5 m); here that solve is not taken.
inline constexpr double kSecantContactShare = 1e-3;

// finite_rotation: moves every block's secant angle to the r0 just solved; returns how many
// were further from it than their tolerance (0: the step's T is consistent with its r0):
// kSecantDisplacementShare of w0, or for a block in closed contact kSecantContactShare of
// its contacts' smallest allowance if that is more.
// `off`, if given, receives the indices of the blocks beyond their tolerance.
int follow_secant_angles(const World& world, const std::vector<Contact>& contacts,
                         const Eigen::VectorXd& d, std::vector<double>& angles,
                         std::vector<int>* off = nullptr);

// Whether block b's secant angle `angle` is off the r0 it was solved with by more than the
// free blocks' tolerance (kSecantDisplacementShare of w0).
bool free_secant_off(const World& world, const Block& b, double r0, double angle);

// Each block's tolerance of follow_secant_angles (m at its farthest vertex):
// kSecantDisplacementShare of w0, or for a block in closed contact kSecantContactShare of its
// contacts' smallest allowance if that is more.
std::vector<double> secant_tolerances(const World& world, const std::vector<Contact>& contacts);

// The displacement at block b's farthest vertex by which the strain rate's share of its
// quadratic velocity terms (rotating_inertia.hpp: the acceleration L^2 y, L = omega J + D;
// the share omega tr(D) J + D^2) changes over a step of dt when its spin goes from `was` to
// `now`: dt^2 / 2 |share_now - share_was| reach. The step's
// inertia is taken at the spin it was assembled with; an answer is consistent with its own
// mean rates when this is within the block's secant tolerance.
double spin_error(const Block& b, const Spin& was, const Spin& now, double dt);

}  // namespace dda
