// A validated scene: what the user asked for, in user units (SI), immutable once built.
// io/ turns a JSON file into this; solver/ turns this into a World. Every field here has
// already been checked (io/scene_reader.cpp), so the solver only asserts.
#pragma once

#include <optional>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "contact/joint_law.hpp"
#include "kinematics/polygon.hpp"
#include "common/enum_names.hpp"
#include "kinematics/types.hpp"
#include "solver/random_strength_spec.hpp"
#include "solver/base_motion.hpp"
#include "solver/joint_water.hpp"
#include "materials/material_types.hpp"

namespace dda {

// How the block configuration is moved at the end of a step: one value per line of
// solver/rotation/treatments.def, which says what each is. Each is a RotationTreatment in a
// file of its own (solver/rotation/treatment.hpp), found through one table (treatment_for).
enum class RotationUpdate {
#define DDA_TREATMENT(value, name, treatment) value,
#include "solver/rotation/treatments.def"
#undef DDA_TREATMENT
};

using RotationUpdateName = EnumName<RotationUpdate>;

// The scene names of the treatments (the contract of control.rotation_update).
inline constexpr RotationUpdateName kRotationUpdateNames[] = {
#define DDA_TREATMENT(value, name, treatment) {RotationUpdate::value, name},
#include "solver/rotation/treatments.def"
#undef DDA_TREATMENT
};

inline std::string_view rotation_update_name(RotationUpdate u) {
  return name_in(kRotationUpdateNames, u);
}

// How each step's frictional contact problem is solved (control.contact_solver;
// docs/contact-solver.md).
enum class ContactSolver {
  // Shi's open-close iteration (1988): every solve taken whole, each contact choosing its
  // next mode from its history; a step whose modes still change after max_open_close solves
  // is cut. The reference path.
  OpenClose,
  // A semismooth Newton iteration with a line search over the regularised Coulomb law
  // (solver/contact_newton.hpp): modes read off the iterate, never cycling.
  Newton,
};

inline constexpr EnumName<ContactSolver> kContactSolverNames[] = {
    {ContactSolver::OpenClose, "open_close"},
    {ContactSolver::Newton, "newton"},
};

// How a deformable block's inertia is taken (control.inertia; docs/rotating-inertia.md).
enum class Inertia {
  // Shi's: the mass matrix int rho T^T T over the current polygon at the given density, and
  // nothing else. A spinning block then feels no centrifugal load, and its mass follows its
  // area.
  Shi,
  // The pseudo-rigid body's (Cohen and Muncaster 1988), exact for a DDA block's affine
  // motion: mass and material inertia kept (density x initial area / current area), and the
  // quadratic velocity terms of the block-frame strains (centripetal, Coriolis;
  // kinematics/rotating_inertia.hpp). Needs a treatment that keeps a block frame.
  PseudoRigid,
};

// The scene and summary names of the inertias (control.inertia; "auto" is the absence of a
// choice, not a value).
inline constexpr EnumName<Inertia> kInertiaNames[] = {
    {Inertia::PseudoRigid, "pseudo_rigid"},
    {Inertia::Shi, "shi"},
};

// A block material: the material library's parameters (materials/
// material_types.hpp: elastic, Drucker-Prager or Mohr-Coulomb, each with its own) under the
// scene's name for them. Their plane mode is the scene's (the reader sets it).
struct Material {
  std::string name;
  MaterialParameters parameters;
  // Blocks of this material are rigid unless their own `rigid` says otherwise (BlockSpec).
  // Elastic models only (the reader rejects a rigid plastic material: a block without
  // strain cannot yield); young still counts towards the "auto" penalty.
  bool rigid = false;
};

// An elastic material (the common case in code-built scenes and tests).
inline Material elastic_material(std::string name, double density, double young,
                                 double poisson) {
  Material m;
  m.name = std::move(name);
  m.parameters.density = density;
  m.parameters.young = young;
  m.parameters.poisson = poisson;
  return m;
}

// Mohr-Coulomb joint between blocks (Shi 1988): friction, cohesion and tensile strength.
// Cohesion and tensile strength act only on contacts that exist (closed) at the start (or
// are bonded by a stage). What a bonded contact does when it fails depends on `law`.
struct JointMaterial {
  std::string name;
  double friction_angle = 0.0;    // degrees, [0, 90)
  double cohesion = 0.0;          // Pa, >= 0
  double tensile_strength = 0.0;  // Pa, >= 0
  JointLawKind law = JointLawKind::BrittleBond;
  // Slip weakening (docs/scene-format.md, joint_materials): residual_slip 0 is none.
  double residual_friction_angle = 0.0;  // degrees
  double residual_cohesion = 0.0;        // Pa
  double residual_slip = 0.0;            // m
  // Barton-Bandis (docs/scene-format.md, joint_materials): jcs 0 is none; with it,
  // friction_angle is the residual angle phi_r.
  double jrc = 0.0;
  double jcs = 0.0;  // Pa
};

// The joint used when a scene of one block names none: frictionless, no strength.
inline const JointMaterial kBuiltInDefaultJoint{"default", 0.0, 0.0, 0.0, JointLawKind::BrittleBond};

// A pair of blocks whose contacts use a named joint material instead of "default".
struct JointSpec {
  int block_a = -1;
  int block_b = -1;
  int material = 0;  // index into Scene::joint_materials
};

struct BlockSpec {
  Polygon vertices;              // counter-clockwise, simple, non-zero area
  int material = 0;              // index into Scene::materials
  bool fixed = false;            // fixed blocks carry no unknowns
  Vec3 velocity = Vec3::Zero();  // [vx, vy, omega] at the centroid (m/s, rad/s)
  Vec3 initial_stress = Vec3::Zero();  // [sxx, syy, sxy] (Pa), tension positive
  // Rigid: 3 unknowns (u0, v0, r0), no strain, no stress (initial_stress must be zero).
  // Unset: the material's Material::rigid; set, it overrides the material's.
  std::optional<bool> rigid;
  // Per edge (edge k from vertex k to vertex k + 1): the joint material (index into
  // Scene::joint_materials) of the joint the edge lies on, -1 for none; contacts on an edge
  // with one act with it, the others with their pair's (JointSpec). Empty: none.
  std::vector<int> edge_joints;
  // Per edge: the rock bridge smeared along it (docs/scene-format.md, "edge_bridges"): the
  // joint material of the intact rock (-1: none) and the share of the edge it covers.
  struct EdgeBridge {
    int material = -1;
    double share = 0.0;
  };
  std::vector<EdgeBridge> edge_bridges;  // empty: none
};

// Whether block `b` of material `m` is rigid: its own key if given, else its material's.
inline bool is_rigid(const BlockSpec& b, const Material& m) { return b.rigid.value_or(m.rigid); }

// A fixed point: the material point of `block` at `point` is held there by a penalty spring.
struct PinSpec {
  Vec2 point = Vec2::Zero();
  int block = -1;  // resolved by the reader: the block containing the point
};

// A monitoring point: a named material point of a block whose position, displacement and
// velocity are written to monitors.csv at every output step.
struct MonitorSpec {
  std::string name;
  Vec2 point = Vec2::Zero();
  int block = -1;  // resolved by the reader: the block containing the point
};

// A constant force (N per metre of thickness) applied at a material point of a block.
struct PointLoadSpec {
  Vec2 point = Vec2::Zero();
  Vec2 force = Vec2::Zero();
  int block = -1;
};

// A rock bolt or cable (docs/scene-format.md, "bolts"): an axial bar from material point
// `from` of one block to `to` of another (a fixed block is the ground it is anchored in).
struct BoltSpec {
  std::string name;
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  int block_from = -1;  // resolved by the reader: the blocks containing the points
  int block_to = -1;
  double stiffness = 0.0;   // N/m per metre of thickness
  double pretension = 0.0;  // N/m, the force at installation
  double yield_force = std::numeric_limits<double>::infinity();        // N/m
  double rupture_extension = std::numeric_limits<double>::infinity();  // m of plastic extension
};

// Shi's usual allowed penetration, as a share of w0 (half the larger side of the bounding
// box of all blocks at the start): ControlSettings::allowed_penetration's "auto".
inline constexpr double kAutoPenetrationShare = 4e-4;

// Half the larger side of the bounding box of all the blocks' vertices (m): Shi's w0.
inline double scene_w0(const std::vector<Polygon>& polygons) {
  const Box box = bounding_box(polygons);
  return 0.5 * (box.max - box.min).maxCoeff();
}

struct ControlSettings {
  // Time step (s). One value, or a list used cyclically (the paper alternates 0.01/0.02 s).
  std::vector<double> time_steps{0.01};
  // Exactly one of the two is set: the number of completed steps, or the end time (s).
  std::optional<int> steps;
  std::optional<double> end_time;
  // A step in which any vertex moves more than ratio * w0 (w0 = half the larger extent of
  // the scene's bounding box at the start) is cut and redone. Shi's g2; range (0, 1].
  double max_displacement_ratio = 0.01;
  // Share of the end-of-step velocity carried into the next step: 1 dynamic, 0 static
  // (velocities dropped each step). Range [0, 1].
  double dynamic_coefficient = 1.0;
  RotationUpdate rotation_update = RotationUpdate::FiniteRotationPolar;
  // Penalty stiffness of pins (N/m per metre of thickness); nullopt means "auto"
  // (50 x the largest Young's modulus, Shi's usual g0; see README).
  std::optional<double> penalty;
  // Write history rows and a VTK frame every this many steps (and at the start and end).
  int output_every = 10;
  // How the VTK frames store their arrays (scene key `vtk_format`): true ("binary", the
  // default) appends them zlib-compressed after the XML, as ParaView writes; false ("ascii")
  // writes them as text (io/vtk_polydata.hpp, docs/output-format.md).
  bool vtk_binary = true;
  // Open-close iterations allowed per step before the step is cut (dt x 0.3) and redone
  // (Shi's usual limit; docs/closed-forms.md). Range >= 2.
  int max_open_close = 8;
  // Augmented-Lagrangian rounds allowed per step (penetration control at a fixed penalty,
  // solver/step.cpp) before a step whose contacts are deeper than allowed_penetration is
  // cut. Range 0 (off: cutting only, as Shi) to 50.
  int max_augmentations = 5;
  // How the global system is solved: true ("reuse", the default) keeps the
  // factor across iterations and steps (rank-one updates by changed contact springs,
  // conjugate gradients for the rest, refactorised when that costs less); false
  // ("factorise") factorises every system afresh, the plain reference path. Both give the
  // same answer to ~1e-10 relative (CholmodSolver::kCgTolerance).
  bool reuse_factor = true;
  // Largest penetration allowed at a contact after a step (m); nullopt means "auto":
  // kAutoPenetrationShare x w0 (Shi's usual value). A step exceeding it is cut and redone.
  std::optional<double> allowed_penetration;
  // The energy guard (docs/energy-balance.md): the run stops as diverged (exit 3) when the
  // unexplained energy gain passes this share of the scene's energy scale. Range > 0; the
  // default 0.02 is four times the largest gain of the hard cases (verification/hard-cases)
  // at their coarsest time step and far below the gains of the faults it exists for.
  double energy_tolerance = 0.02;
  // Energy the account loses without a term that books it (a remainder below minus the
  // tolerance share of the scale) is always reported (summary.json's energy
  // `losses_beyond_tolerance`, and a warning at the end of `dda run`); true also stops the
  // run as diverged there, as a gain does (scene key `energy_losses`: "report" or "stop").
  bool stop_on_energy_loss = false;
  // The contact solver of every step (see ContactSolver; the converged one by default,
  // Shi's loop kept as the reference path).
  ContactSolver contact_solver = ContactSolver::Newton;
  // Block inertia (docs/rotating-inertia.md). nullopt means "auto": PseudoRigid for the
  // treatments that keep a block frame (local_frame, local_frame_as_printed,
  // finite_rotation), Shi for the others, which have no block-frame strain to carry it.
  std::optional<Inertia> inertia;
};

// A joint material's properties replaced during one stage (StageSpec::joint_materials).
struct StageJoint {
  int joint = 0;           // index into Scene::joint_materials
  JointMaterial material;  // the scene's entry with the stage's properties put in
};

// One stage of a staged run (Scene::stages; docs/scene-format.md, "stages"). Its settings
// hold for `duration` seconds and then the next stage's take over. Settings the stage
// leaves out are already resolved to control's by the reader.
struct StageSpec {
  double duration = 0.0;               // s, > 0
  double dynamic_coefficient = 1.0;    // [0, 1]
  // Gravity = scene gravity x a factor, linear in time from `gravity_from` at the stage's
  // start to `gravity_to` at its end (equal: a constant factor). Each >= 0.
  double gravity_from = 1.0;
  double gravity_to = 1.0;
  bool gravity_ramp = false;           // given as "gravity_ramp" (else "gravity_factor")
  std::vector<double> time_steps;      // s, each > 0, not empty; used cyclically
  std::vector<StageJoint> joint_materials;  // properties replaced during this stage only
  // At the stage's start, every closed contact whose joint (as this stage has it) has
  // cohesion or tensile strength becomes bonded (contact/bonding.hpp).
  bool bond_closed_contacts = false;
  // Blocks removed at the stage's start (indices into Scene::blocks; each removed once in a
  // run): an excavation lift (solver/excavation.hpp).
  std::vector<int> excavate;
};

struct Scene {
  std::string source;              // file name, or "built-in default scene"
  Vec2 gravity{0.0, -9.81};        // m/s^2
  PlaneMode plane = PlaneMode::Strain;
  ControlSettings control;
  std::vector<Material> materials;
  // Joint materials; index 0 is always "default", used by every pair not in `joints`.
  std::vector<JointMaterial> joint_materials{kBuiltInDefaultJoint};
  std::vector<JointSpec> joints;
  std::vector<BlockSpec> blocks;
  std::vector<PinSpec> pins;
  std::vector<PointLoadSpec> point_loads;
  std::vector<MonitorSpec> monitors;
  std::vector<BoltSpec> bolts;
  // Joint water pressure from a phreatic line (docs/scene-format.md, "water"); none if unset.
  std::optional<WaterTable> water;
  // Base shaking: the fixed blocks' prescribed acceleration (docs/scene-format.md,
  // "base_motion"); none if unset.
  std::optional<BaseMotion> base_motion;
  // Stages run in order (empty: none, the run follows `control` alone). With stages,
  // control.end_time is the sum of their durations and control.steps is unset.
  std::vector<StageSpec> stages;
  // Strengths `dda fos --samples` draws at random (docs/scene-format.md,
  // "random_strengths"); empty: none. Other commands use the scene's own values.
  RandomStrengths random_strengths;
  // Things worth telling the user that do not stop the run (e.g. an unused joint material).
  std::vector<std::string> warnings;
};

}  // namespace dda
