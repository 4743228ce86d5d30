// The world the step loop advances: the materials' table, blocks (each one struct, its
// fields marked cold, fixed at construction, and hot, advanced every step; a block names its
// material by index), pins, point loads, time. Built once from a validated Scene
// (make_world), then owned by the step loop.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "contact/contact.hpp"
#include "contact/joint_law.hpp"
#include "kinematics/polygon.hpp"
#include "kinematics/types.hpp"
#include "materials/material_types.hpp"
#include "solver/elements/bolt_law.hpp"
#include "solver/joint_water.hpp"
#include "solver/scene.hpp"
#include "solver/stages.hpp"

namespace dda {

// Contact search distance of two blocks as a multiple of what both may move in a step: a
// pair of vertices cannot close a gap wider than the sum of their step limits, so contacts
// the step could make are all found (Shi's 2.5 x g2 x w0 for two blocks of the scene's size).
inline constexpr double kSearchDistanceFactor = 2.5;
// A block's reach (Block::reach) counts its predicted translation this many times: the
// prediction takes velocity and gravity only (contacts and loads change it); a step that
// moves a vertex beyond the reach is cut all the same (max_displacement_share).
inline constexpr double kReachSafety = 1.5;

struct Block {
  // ---- cold: fixed at construction ----
  Polygon initial_vertices;     // X: the material points of the vertices at the start
  Vec2 initial_centroid = Vec2::Zero();  // Xc: the reference point at the start
  int material = 0;  // index into World::materials (material_of, elastic_of)
  bool fixed = false;
  // Per edge (k: vertex k to k + 1), the joint law of the joint it lies on, -1 none; empty
  // when no edge has one (BlockSpec::edge_joints; joint_of_contact).
  std::vector<int> edge_joints;
  std::vector<BlockSpec::EdgeBridge> edge_bridges;  // per edge, empty when none has one
  // Given in the global frame at the start, where the block frame is the global one; the
  // local-frame treatments hold it in the block frame (it turns with the block). A plastic
  // block's four components: initial_stress4.
  Vec3 initial_stress = Vec3::Zero();
  double initial_area = 0.0;
  // J0 = rho int (X - Xc)(X - Xc)^T dA over the initial polygon (kg m^2 per metre): the
  // material inertia behind the rotating-frame terms (kinematics/rotating_inertia.hpp).
  Mat2 material_inertia = Mat2::Zero();
  int first_dof = -1;  // index of u0 in the global system; -1 for fixed blocks
  // Removed by an excavation stage (solver/excavation.hpp): fixed from then on, in no
  // contact and in no energy term, kept in place only so that block indices stay the same.
  bool excavated = false;
  // The most any of its vertices may move in one step (m): max_displacement_ratio x half the
  // larger side of the block's own bounding box at the start; 0 for a fixed block, which does
  // not move. Shi's g2 measured against the block, not the scene: a small block next to a
  // wide floor may not jump by a share of the floor, and the contact search (2.5 x this,
  // pair by pair: contact_detection.hpp) stays as local as the blocks (docs/contacts.md,
  // "Search distance").
  double step_limit = 0.0;
  // The most any of its vertices may move this step (m), its translation included: the step
  // limit plus kReachSafety x the translation its velocity and gravity predict for the
  // step's first attempt (set_reaches, at each step's start; step_limit until the first
  // step). The motion relative to the block's translation is held to step_limit (the
  // rotation and strain a step linearises); the translation, which every treatment takes
  // exactly, only to the reach, which the contact search covers (docs/contacts.md).
  double reach = 0.0;
  double size = 0.0;  // half the larger side of its bounding box at the start (m), as w0
  // A rigid block keeps the six slots of d like any block, but the
  // linear system solves only its u0, v0, r0 (BlockSystem's dof map): its strain increments
  // are exactly zero, it has no elastic matrix (D = 0) and no initial stress.
  bool rigid = false;
  // Plastic blocks take their stress from the material library over the strain
  // their treatment accumulates (src/solver/material_coupling.hpp); elastic blocks never
  // touch it. A free, deformable block of a plastic model.
  bool plastic = false;

  // ---- hot: advanced every step ----
  Polygon vertices;                 // current configuration
  Moments moments;                  // of `vertices` (reference point = current centroid)
  Vec2 translation = Vec2::Zero();  // total displacement of the reference point (paper Eq. 14)
  // Total rotation r0 (rad, counter-clockwise; paper Eq. 15). Also the frame angle: the
  // block's frame (paper Fig. 1) is the global frame turned by this angle.
  double rotation = 0.0;
  Vec3 strain = Vec3::Zero();  // total strain [exx, eyy, gxy], global frame
  // Total strain in the block frame [e^x, e^y, g^xy]. Accumulated there by the local-frame
  // treatments (paper Eq. 16); the others accumulate `strain` and derive this from it.
  Vec3 local_strain = Vec3::Zero();
  Vec3 stress = Vec3::Zero();  // [sxx, syy, sxy] (Pa), global frame
  // Rates of the six unknowns at the end of the last step (strain rates in the global frame).
  Vec6 velocity = Vec6::Zero();
  // Strain rates in the block frame (paper Section 4, steps 6 to 9): advanced by the
  // local-frame treatments, which turn them into velocity's strain rates; the others derive
  // them from velocity (finite_rotation_polar's deformable blocks: D, the spatial rate).
  Vec3 local_strain_rate = Vec3::Zero();
  // The last step's rotation increment r0 (rad): sin_variable builds T' from it (Cheng and
  // Zhang), finite_rotation starts its secant iteration from it.
  double last_rotation_increment = 0.0;
  // finite_rotation_polar: the last step's block-frame strain increment, the change of the
  // polar decomposition's strain (the strain rate's increment).
  Vec3 last_local_increment = Vec3::Zero();
  // Plastic blocks: the material state (plastic strain, eps_p) at the end of the last step,
  // the out-of-plane stress and the return branch it took.
  MaterialState material_state;
  double szz = 0.0;
  Branch branch = Branch::Elastic;
};

// A pin holds a material point of a block at its anchor with a penalty spring.
struct Pin {
  int block = -1;
  Vec2 anchor = Vec2::Zero();   // where the spring pulls the point (the start, unless moved)
  // The pinned point at the start: its material point X for the local-frame treatments,
  // which place it by the block's map from the initial configuration.
  Vec2 initial = Vec2::Zero();
  Vec2 current = Vec2::Zero();  // where that material point is now
};

struct PointLoad {
  int block = -1;
  Vec2 initial = Vec2::Zero();  // the loaded material point at the start
  Vec2 current = Vec2::Zero();  // present position of the loaded material point
  Vec2 force = Vec2::Zero();    // N per metre of thickness, constant in the global frame
};

// A monitoring point (MonitorSpec): carried with its block like a load, observed only.
struct Monitor {
  std::string name;
  int block = -1;
  Vec2 initial = Vec2::Zero();  // the material point at the start
  Vec2 current = Vec2::Zero();  // where it is now
};

// One end of a bolt (Bolt): a material point carried with its block like a load.
struct BoltEnd {
  int block = -1;
  Vec2 initial = Vec2::Zero();  // the material point at the start
  Vec2 current = Vec2::Zero();  // where it is now
};

// A rock bolt or cable (scene "bolts"; solver/elements/bolt_element.hpp): an axial bar
// between two material points, World::bolt_ends[2 i] (end a) and [2 i + 1] (end b), with
// the law of solver/elements/bolt_law.hpp. Its force acts along the line between its ends
// at each step's start.
struct Bolt {
  std::string name;
  BoltLaw law;
  // The plastic extension (m, summed over the steps whatever its sign) at which the bar
  // breaks; infinity: never.
  double rupture_extension = std::numeric_limits<double>::infinity();
  double force = 0.0;              // axial force now, N/m, tension positive
  double plastic_extension = 0.0;  // summed |dl_p| so far, m
  bool broken = false;             // broken bars carry nothing from the step they broke in
  double broken_at = 0.0;          // s: the time of the step it broke in
};

// Whether bolt b, not broken, holds its capacity now (the mode its next step starts in is
// yielding): what the outputs call "yielding".
inline bool bolt_yielding(const Bolt& b) {
  return !b.broken && start_bolt_mode(b.law, b.force) != BoltMode::Elastic;
}

// The energy account's running sums since the start of the run (J per metre of thickness;
// solver/energy.hpp, docs/energy-balance.md).
struct EnergyLedger {
  double load_work = 0.0;             // work of point loads and initial stresses
  // Work of the contacts' augmented-Lagrangian multipliers (ContactState::rest_shift), the
  // force p s each closed contact adds to its spring, on the contact's normal motion.
  double multiplier_work = 0.0;
  double friction_dissipation = 0.0;  // by sliding contacts (never negative)
  double plastic_dissipation = 0.0;   // by plastic blocks' plastic strain and yielding bolts
  double damping_dissipation = 0.0;   // by the implicit time integration and the dynamic coefficient
  double friction_gain = 0.0;         // friction work that pushed forward (part of the remainder)
  double contact_energy = 0.0;        // stored in contact and pin springs after the last step
  // What excavated blocks took out of the scene as they went (solver/excavation.hpp): their
  // kinetic, potential and strain energy and their contacts' and bolts' spring energy.
  double excavation = 0.0;
  double initial_total = 0.0;         // kinetic + potential + strain + contact at the start
  double remainder = 0.0;             // unexplained: now - start - work + dissipations
  double remainder_max = 0.0;         // the largest remainder so far (gain)
  int remainder_max_step = 0;         // the step where it was reached
  double remainder_min = 0.0;         // the most negative remainder so far (energy lost unbooked)
  int remainder_min_step = 0;         // the step where it was reached
  // The scene's own energy scale, against which the remainder is judged: the largest of
  // the energy it starts with (less potential), the work gravity and the point loads would
  // do moving every free block by w0, the largest kinetic energy and |load work| so far,
  // and at least the free blocks' strain energy at a strain of kRestScaleStrain (a scene
  // at rest).
  double scale = 0.0;
};

// The step size that remembers (solver/step.cpp, advance_step): once a
// step has been cut, the steps after it start from the step that worked instead of the
// schedule's, and grow back towards it. While the schedule is followed it holds nothing.
struct StepSizeMemory {
  double next = 0.0;  // s: the longest step the next one tries (it caps the schedule); 0: none
};

// A material as the blocks use it (Block::material is its index).
struct WorldMaterial {
  MaterialParameters parameters;  // the scene's, in the scene's plane mode
  Mat3 elastic = Mat3::Zero();    // D of `parameters`: s = D e (plane strain or stress)
};

struct World {
  // The scene's materials, in its order; strength-reduction trials reduce them here.
  std::vector<WorldMaterial> materials;
  std::vector<Block> blocks;
  std::vector<Pin> pins;
  std::vector<PointLoad> loads;
  std::vector<Monitor> monitors;
  std::vector<Bolt> bolts;
  std::vector<BoltEnd> bolt_ends;  // two per bolt: a, b
  // Joint water pressure (solver/joint_water.hpp); the forces it puts on the blocks are the
  // step's (StepContext::water_forces, from present_water_forces).
  std::optional<WaterTable> water;
  // Base shaking (solver/base_motion.hpp): the ground's acceleration history; the world is
  // advanced in the ground's frame.
  std::optional<BaseMotion> base_motion;
  Vec2 gravity = Vec2::Zero();
  // control.inertia resolved: the pseudo-rigid body's inertia (mass kept, rotating-frame
  // terms) for the deformable blocks; false: Shi's.
  bool pseudo_rigid = false;
  PlaneMode plane = PlaneMode::Strain;
  ControlSettings control;
  double penalty = 0.0;  // resolved stiffness of pins and contact normal springs (N/m)
  double w0 = 0.0;       // half the larger extent of the scene at the start (m)
  double allowed_penetration = 0.0;  // resolved (m)
  // The largest contact search distance of any pair (pair_search_distance): 2.5 x the largest
  // step limit + allowed_penetration (m). The carried broad phase's margin and joint water's
  // face tolerance use it.
  double search_distance = 0.0;

  // Joint laws: index 0 "default", used by every block pair not in `pair_joint`.
  std::vector<JointLaw> joint_laws;
  std::unordered_map<std::uint64_t, int> pair_joint;  // key pair_key(i, j), i < j
  // Slots of the step's increments d (6 per free block, rigid or not); the linear system
  // solves fewer when blocks are rigid (BlockSystem::unknowns()).
  int dof_count = 0;

  // The contacts of the present configuration and the state they carry from step to step
  // (mode, anchor, bond; contact/carry_over.hpp). Detected again at the start of every step.
  std::vector<Contact> contacts;

  double time = 0.0;  // s
  int step = 0;       // completed steps
  StepSizeMemory step_size;  // forgotten when a stage begins and when a fos trial begins
  EnergyLedger energy;
  // The scene's stages (solver/stages.hpp): the one running and what its settings replaced
  // in gravity, control and joint_laws above. Empty without stages.
  StagePlan stages;
};

// A free block's row of 6 x 6 blocks in the global system (BlockSystem): its first slot / 6.
inline int block_row(const Block& b) { return b.first_dof / 6; }

// The joint law contact c acts with in this step: its joint material's (with its rock bridge
// smeared in), at the normal stress it started the step with (a Barton-Bandis joint's
// friction) and the slip it has accumulated (law_at_slip: a slip-weakening joint's strength
// falls with it).
inline JointLaw contact_law(const World& world, const Contact& c) {
  return law_at_slip(law_at_stress(contact_joint_law(world.joint_laws, c), c.start_normal_force, c.length),
                     c.state.slip_sum);
}

// The block's material parameters.
inline const MaterialParameters& material_of(const World& world, const Block& b) {
  return world.materials[static_cast<std::size_t>(b.material)].parameters;
}

// The block's D, s = D e: its material's, and zero for a rigid block. A rigid block has no
// strain and so no stiffness and no stress: D = 0 makes every strain term (assembly,
// stress, strain energy) vanish even where the zero strain does not already.
inline const Mat3& elastic_of(const World& world, const Block& b) {
  static const Mat3 kNoStiffness = Mat3::Zero();
  return b.rigid ? kNoStiffness : world.materials[static_cast<std::size_t>(b.material)].elastic;
}

// A plastic block's initial stress as (sxx, syy, szz, sxy) for the material library:
// szz = nu (sxx + syy), the plane-strain stress an elastic history would have left.
inline Vec4 initial_stress4(const World& world, const Block& b) {
  const Vec3& s0 = b.initial_stress;
  return Vec4(s0[0], s0[1], material_of(world, b).poisson * (s0[0] + s0[1]), s0[2]);
}


// Contact search distance between blocks i and j (m): 1.25 x the sum of what their vertices
// may move in a step (their reaches), so every contact the step could close is found with a quarter to
// spare, plus the allowed penetration, so a contact that starts the step that deep (the most
// a step may leave) is found from inside too.
inline double pair_search_distance(const World& world, int i, int j) {
  return world.allowed_penetration +
         0.5 * kSearchDistanceFactor *
             (world.blocks[static_cast<std::size_t>(i)].reach +
              world.blocks[static_cast<std::size_t>(j)].reach);
}

// Sets every free block's reach (Block::reach) for a step whose first attempt is dt long.
void set_reaches(World& world, double dt);

// The joint law index for contacts between blocks i and j.
int joint_of_pair(const World& world, int i, int j);
// The joint law index of a contact of a vertex of `vertex_block` on edge `edge` of
// `edge_block`: the edge's joint (Block::edge_joints) if it lies on one, else the pair's. A
// pair that shares a bedding plane and a cross joint gets each joint's law where it acts,
// and a pair that touches only at a corner the law of the joint the corner rests on.
int joint_of_contact(const World& world, int vertex_block, int edge_block, int edge);

// The scene's penalty (N/m): control.penalty, or "auto", 50 times the largest Young's modulus
// of the materials the blocks use.
double resolve_penalty(const Scene& scene);

// Builds the world from a validated scene: geometry, elastic matrices, dof numbering,
// resolved penalty and w0.
World make_world(const Scene& scene);

// The density the block's mass matrix and weight take over its present polygon (kg/m^3).
// With the pseudo-rigid body's inertia the mass is kept, so the density falls as the area
// grows (exact for a homogeneous deformation); with Shi's, it is the material's.
inline double density_now(const World& world, const Block& b) {
  const double density = material_of(world, b).density;
  return world.pseudo_rigid ? density * b.initial_area / b.moments.area : density;
}

// The block's mass (kg per metre of thickness): its weight is this times gravity.
inline double block_mass(const World& world, const Block& b) {
  return density_now(world, b) * b.moments.area;
}

// Kinetic energy 1/2 v^T M v of one block (J per metre), from its velocity and mass matrix.
double kinetic_energy(const World& world, const Block& block);

// The allowed penetration of a contact between blocks i and j (m): the scene's
// allowed_penetration when the scene gives one, or with Shi's open-close loop (his rule,
// kAutoPenetrationShare x w0, one value for the whole scene); with the converged contact
// solver and "auto", kAutoPenetrationShare x the size of the smaller free block of the two,
// so that a fixed block far away does not loosen every contact (one unrelated block 1000 km
// off made a scene's allowance 200 m), and a pebble on a 50 m base is held to its own scale.
inline double contact_allowance(const World& world, int i, int j) {
  if (world.control.allowed_penetration || world.control.contact_solver != ContactSolver::Newton) {
    return world.allowed_penetration;
  }
  double size = INFINITY;
  for (const int k : {i, j}) {
    const Block& b = world.blocks[static_cast<std::size_t>(k)];
    if (!b.fixed) size = std::min(size, b.size);
  }
  return std::isfinite(size) ? kAutoPenetrationShare * size : world.allowed_penetration;
}

}  // namespace dda
