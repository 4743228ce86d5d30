// The world the step loop advances: blocks (cold data beside hot state), pins, point loads,
// time. Built once from a validated Scene (make_world), then owned by the step loop.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "contact/joint_law.hpp"
#include "kinematics/polygon.hpp"
#include "kinematics/types.hpp"
#include "solver/scene.hpp"

namespace dda {

struct Block {
  // ---- cold: fixed at construction ----
  Polygon initial_vertices;
  int material = 0;
  bool fixed = false;
  double density = 0.0;   // kg/m^3
  Mat3 elastic = Mat3::Zero();  // D, s = D e (plane strain or stress)
  Vec3 initial_stress = Vec3::Zero();
  double initial_area = 0.0;
  int first_dof = -1;  // index of u0 in the global system; -1 for fixed blocks

  // ---- hot: advanced every step ----
  Polygon vertices;               // current configuration
  Moments moments;                // of `vertices` (reference point = current centroid)
  double rotation = 0.0;          // total rotation r0 (rad, counter-clockwise)
  Vec3 strain = Vec3::Zero();     // total strain [exx, eyy, gxy], global frame
  Vec3 stress = Vec3::Zero();     // [sxx, syy, sxy] (Pa), global frame
  Vec6 velocity = Vec6::Zero();   // rates of the six unknowns at the end of the last step
};

// A pin holds a material point of a block at its anchor with a penalty spring.
struct Pin {
  int block = -1;
  Vec2 anchor = Vec2::Zero();   // where the point was at the start
  Vec2 current = Vec2::Zero();  // where that material point is now
};

struct PointLoad {
  int block = -1;
  Vec2 current = Vec2::Zero();  // present position of the loaded material point
  Vec2 force = Vec2::Zero();    // N per metre of thickness, constant in the global frame
};

struct World {
  std::vector<Block> blocks;
  std::vector<Pin> pins;
  std::vector<PointLoad> loads;
  Vec2 gravity = Vec2::Zero();
  PlaneMode plane = PlaneMode::Strain;
  ControlSettings control;
  double penalty = 0.0;  // resolved stiffness of pins and contact normal springs (N/m)
  double w0 = 0.0;       // half the larger extent of the scene at the start (m)
  double allowed_penetration = 0.0;  // resolved (m)
  double search_distance = 0.0;      // contact search distance 2.5 x ratio x w0 (m)

  // Joint laws: index 0 "default", used by every block pair not in `pair_joint`.
  std::vector<JointLaw> joint_laws;
  std::unordered_map<std::uint64_t, int> pair_joint;  // key pair_key(i, j), i < j
  int dof_count = 0;     // unknowns in the global system (6 per free block)

  double time = 0.0;  // s
  int step = 0;       // completed steps
};

// Key of an unordered block pair in World::pair_joint.
inline std::uint64_t pair_key(int i, int j) {
  const auto lo = static_cast<std::uint64_t>(i < j ? i : j);
  const auto hi = static_cast<std::uint64_t>(i < j ? j : i);
  return (hi << 32) | lo;
}

// The joint law index for contacts between blocks i and j.
int joint_of_pair(const World& world, int i, int j);

// Builds the world from a validated scene: geometry, elastic matrices, dof numbering,
// resolved penalty and w0.
World make_world(const Scene& scene);

// Kinetic energy 1/2 v^T M v of one block (J per metre), from its velocity and mass matrix.
double kinetic_energy(const Block& block);

}  // namespace dda
