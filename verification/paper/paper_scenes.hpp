// The scenes of the paper reproduction (Jiang and Zheng 2015, Section 5) and of the
// speed-against-error sweeps, built in code as plain Scene structs (no JSON), so that the
// program depends only on the solver's API. Geometry lives here and nowhere else.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "solver/scene.hpp"

namespace dda::paper {

// Paper Section 5: unit weight 28 kN/m^3 (density = 28e3 / 9.81 kg/m^3), E = 2 GPa, nu = 0.25.
inline constexpr double kGravity = 9.81;
inline constexpr double kDensity = 28e3 / kGravity;
inline constexpr double kYoung = 2e9;
inline constexpr double kPoisson = 0.25;

// Regular octagon of circumradius `r` about `centre`, counter-clockwise, first vertex at
// angle `first_angle` (rad) from the +x axis.
Polygon regular_octagon(const Vec2& centre, double r, double first_angle);

// ---- Table 1: the falling octagon on a staircase of fixed blocks ----

// The staircase: `steps` fixed rectangular blocks going down to the right, each `tread` wide
// and `riser` lower than the one before, then a flat run-out (top at y = 0) closed by a wall
// that keeps the rock in the scene; all stand on y = base_y.
struct Staircase {
  int steps = 0;
  double tread = 0.0;    // m
  double riser = 0.0;    // m
  double runout = 0.0;   // m, flat floor after the last step
  double wall_width = 0.0, wall_height = 0.0;  // m, the wall at the end of the run-out
  double base_y = 0.0;   // m, the bottom of every fixed block
};
Staircase table1_staircase();
std::vector<Polygon> staircase_blocks(const Staircase& s);

// How the rock is launched: its centre, the phase of its first vertex, and its initial
// velocity [vx, vy, omega] at the centroid.
struct Launch {
  Vec2 centre;
  double first_angle = 0.0;
  Vec3 velocity = Vec3::Zero();
};
Launch table1_launch(const Staircase& s);

// One of the paper's three time-step settings of Table 1.
struct FallingSetting {
  const char* name;                // short key used in the CSVs
  const char* label;               // as the paper's column header
  std::vector<double> time_steps;  // used cyclically
  int steps;
  double max_displacement_ratio;
};
std::vector<FallingSetting> table1_settings();

// The whole scene: staircase (fixed), octagon (free, the LAST block), friction and
// cohesion 0, penalty and allowed penetration "auto".
Scene falling_octagon_scene(const FallingSetting& setting, int steps, RotationUpdate update);

// ---- Tables 2 and 3: the swinging octagon ----

// Circumscribed diameter 10, vertex A = (0, 0), E = (10, 0); the vertices are A..H
// counter-clockwise (A, then B below-left of the centre, C = (5, -5) at the bottom, ...).
Polygon swinging_octagon();
inline const Vec2 kSwingPin{9.5, 0.0};
// dt 0.02 s, max displacement ratio 0.1, pinned at (9.5, 0), gravity.
Scene swinging_octagon_scene(int steps, RotationUpdate update);

// The swing of the pinned octagon: the angle (rad, counter-clockwise) the line from the pin's
// anchor to the block's centroid has swept since the start, unwrapped step by step (a step
// turns it by far less than pi).
class SwingAngle {
 public:
  SwingAngle(const Vec2& anchor, const Vec2& centroid)
      : anchor_(anchor), start_(std::atan2((centroid - anchor).y(), (centroid - anchor).x())) {}
  // The swing with the centroid now at `centroid`.
  double follow(const Vec2& centroid) {
    const Vec2 now = centroid - anchor_;
    swing_ += std::remainder(std::atan2(now.y(), now.x()) - start_ - swing_, 2.0 * std::numbers::pi);
    return swing_;
  }

 private:
  Vec2 anchor_;
  double start_;
  double swing_ = 0.0;
};

// ---- speed against error ----

// A regular octagon of circumradius 1 spinning at `omega` about its centroid, no gravity.
Scene spinning_block_scene(double dt, int steps, double omega, RotationUpdate update);

// A rigid pendulum: a regular octagon of circumradius 1 centred at the origin, pinned at
// (arm, 0) so that it starts horizontal (theta0 = -90 degrees from the downward vertical).
inline constexpr double kPendulumArm = 0.5;
Scene pendulum_scene(double dt, int steps, RotationUpdate update);

// ---- stress under rotation ----
// A 2 m x 1 m rectangle (long side along x) of the paper's rock, centred at the origin,
// spinning at `omega` (rad/s), no gravity, maximum displacement ratio 1 (no step is cut).
Scene spinning_rectangle_scene(double dt, int steps, double omega, RotationUpdate update);
// A block sliding down an incline (a contact case with a closed form): a fixed triangular
// slope whose top face is the line through the origin at kInclineSlope degrees, and a free
// kInclineBlock[0] x kInclineBlock[1] block standing on it, centred at the origin; joint
// friction kInclineFriction degrees, paper material, Shi's auto penalty; ends at end_time.
// The block is the LAST block.
inline constexpr double kInclineSlope = 30.0;     // degrees
inline constexpr double kInclineFriction = 20.0;  // degrees
inline constexpr double kInclineBlock[2] = {1.0, 0.5};  // m, along and normal to the slope
Scene incline_scene(double dt, double end_time);

// Plane-strain compression of a Mohr-Coulomb specimen through its contacts (a plastic case
// with a closed form): a fixed base, a unit-square specimen (block 1) and a stiff elastic
// platen (block 2) on it, no gravity, frictionless joints, the specimen confined by two
// opposite point loads kPlatenConfining (N per metre) at mid-height of its sides and
// compressed by a pin at the platen's top whose anchor the caller moves down (displacement
// control). Static analysis (dynamic_coefficient 0), light blocks (20 kg/m^3), E = 1e10 Pa,
// nu = 0.25; the specimen's cohesion kPlatenCohesion, friction and dilation kPlatenFriction.
inline constexpr double kPlatenCohesion = 1e6;    // Pa
inline constexpr double kPlatenFriction = 30.0;   // degrees
inline constexpr double kPlatenConfining = 1e6;   // N per metre on a 1 m side: s3 = 1 MPa
Scene platen_scene(double dt, int steps);

}  // namespace dda::paper
