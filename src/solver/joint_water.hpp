// Joint water pressure from a phreatic line: hydrostatic pressure below the line
// acts on the faces of the joints (both faces, pushing the blocks apart), as
// limit-equilibrium slope checks load them (Hoek and Bray, Rock Slope Engineering, ch. 6:
// the uplift U on a sliding plane and the thrust V in a water-filled tension crack). Free
// faces of the blocks carry none: the model is the water in the rock's joints.
#pragma once

#include <vector>

#include "contact/contact.hpp"
#include "kinematics/types.hpp"

namespace dda {

struct World;

// The water table: a polyline with increasing x, extended flat beyond its ends. With a dry
// line, the table lies the share `fill` of the way from it up to the phreatic line at every
// x: a tension crack filled to a random depth (`dda fos --samples`) is one number between a
// dry table and a full one.
struct WaterTable {
  std::vector<Vec2> phreatic_line;  // at least 2 points, x strictly increasing
  double unit_weight = 9810.0;      // N/m^3 (1000 kg/m^3 x 9.81 m/s^2)
  std::vector<Vec2> dry_line;       // empty, or at least 2 points, x strictly increasing
  double fill = 1.0;                // [0, 1]; 1 without a dry line
};

// Height at x of a polyline with increasing x, flat beyond its ends (m).
double polyline_height(const std::vector<Vec2>& line, double x);

// Height of the water table at x (m): the phreatic line's, or with a dry line
// dry(x) + fill (phreatic(x) - dry(x)).
double phreatic_height(const WaterTable& water, double x);

// The pressure force on a segment a-b of a joint face: its size (N per metre, the integral of
// unit_weight x max(0, h(x) - y) along the segment, exact for the piecewise-linear line) and
// where it acts (the centre of pressure; the segment's midpoint when the force is zero).
struct SegmentPressure {
  double force = 0.0;
  Vec2 centre = Vec2::Zero();
};
SegmentPressure segment_pressure(const WaterTable& water, const Vec2& a, const Vec2& b);

// A force on a block at a point, constant over a step.
struct BlockForce {
  int block = -1;
  Vec2 point = Vec2::Zero();
  Vec2 force = Vec2::Zero();  // N per metre
};

// The water forces on the blocks from their joint faces. Each contact that carries a share of
// a face (the halves of the vertex's edges that lie along the contact edge, as for its
// cohesion; contact_detection.cpp) marks that share of the face as wet. The shares of one
// face (one pair of blocks, parallel, lines within `face_tolerance` m: an open joint's two
// sides) are united, so that a part covered from both sides counts once, and the pressure
// on each covered stretch pushes the two blocks apart along the face's normal, at its centre
// of pressure. `polygons[i]` are block i's vertices at the step's start.
std::vector<BlockForce> joint_water_forces(const WaterTable& water,
                                           const std::vector<const Polygon*>& polygons,
                                           const std::vector<Contact>& contacts,
                                           double face_tolerance);

// The water forces on the world's blocks in its present configuration, from its present
// contacts (a step: those detected at its start) and faces up to the contact search distance
// apart (an open joint's two sides are one face); empty without water. The water weighs what
// gravity makes it weigh: a stage that ramps gravity up from zero ramps the pressure with it
// (at full pressure and no weight, a block would be pushed off its joint and its bond broken
// before the consolidation began).
std::vector<BlockForce> present_water_forces(const World& world);

}  // namespace dda
