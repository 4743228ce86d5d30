#include "solver/world.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "kinematics/block_matrices.hpp"
#include "kinematics/rotating_inertia.hpp"
#include "materials/elastic.hpp"
#include "solver/energy.hpp"
#include "solver/rotation/treatment.hpp"

namespace dda {
namespace {

// Shi's usual penalty: about 50 times the largest Young's modulus (per metre of thickness);
// see the docs/closed-forms.md ("Shi's usual controls").
constexpr double kAutoPenaltyFactor = 50.0;

}  // namespace

double resolve_penalty(const Scene& scene) {
  if (scene.control.penalty) return *scene.control.penalty;
  // Only the materials blocks use: a material the scene defines and no block takes must not
  // stiffen every contact (a spare 1e11 Pa entry made a soft block's springs ten times stiffer).
  double largest = 0.0;
  for (const BlockSpec& b : scene.blocks) {
    largest = std::max(largest, scene.materials[static_cast<std::size_t>(b.material)].parameters.young);
  }
  return kAutoPenaltyFactor * largest;
}

World make_world(const Scene& scene) {
  World world;
  world.gravity = scene.gravity;
  world.plane = scene.plane;
  world.control = scene.control;
  world.penalty = resolve_penalty(scene);
  // "auto": the treatment's (RotationTreatment::auto_inertia): the pseudo-rigid inertia
  // where a block frame is kept, except for the paper's method as printed, which keeps Shi's.
  world.pseudo_rigid =
      scene.control.inertia.value_or(treatment_for(scene.control.rotation_update).auto_inertia()) ==
      Inertia::PseudoRigid;

  for (const Material& mat : scene.materials) {
    WorldMaterial m{mat.parameters, Mat3::Zero()};
    m.parameters.plane = scene.plane;
    m.elastic = elastic_matrix(m.parameters.young, m.parameters.poisson, scene.plane);
    world.materials.push_back(std::move(m));
  }

  std::vector<Polygon> polygons;
  for (const BlockSpec& spec : scene.blocks) {
    const Material& mat = scene.materials.at(spec.material);
    Block b;
    b.initial_vertices = spec.vertices;
    b.vertices = spec.vertices;
    b.material = spec.material;
    b.fixed = spec.fixed;
    b.edge_joints = spec.edge_joints;
    b.edge_bridges = spec.edge_bridges;
    // The reader refuses an initial stress or a plastic material for a rigid block.
    b.rigid = is_rigid(spec, mat);
    b.initial_stress = spec.initial_stress;
    b.stress = spec.initial_stress;
    b.plastic = is_plastic(mat.parameters.model()) && !spec.fixed && !b.rigid;
    if (b.plastic) b.szz = initial_stress4(world, b)[2];
    b.moments = polygon_moments(b.vertices);
    b.initial_area = b.moments.area;
    b.initial_centroid = b.moments.centroid;
    b.material_inertia =
        material_inertia(mat.parameters.density, b.moments.sxx, b.moments.syy, b.moments.sxy);
    assert(b.moments.area > 0.0);
    if (!b.fixed) {
      b.first_dof = world.dof_count;
      world.dof_count += 6;
      b.velocity.head<3>() = spec.velocity;
    }
    world.blocks.push_back(std::move(b));
    polygons.push_back(spec.vertices);
  }

  world.w0 = scene_w0(polygons);

  world.allowed_penetration =
      scene.control.allowed_penetration.value_or(kAutoPenetrationShare * world.w0);
  double largest_limit = 0.0;
  for (Block& b : world.blocks) {
    if (b.fixed) continue;
    const Box own = bounding_box(b.initial_vertices);
    b.size = 0.5 * (own.max - own.min).maxCoeff();
    b.step_limit = scene.control.max_displacement_ratio * b.size;
    b.reach = b.step_limit;
    largest_limit = std::max(largest_limit, b.step_limit);
  }
  world.search_distance = kSearchDistanceFactor * largest_limit + world.allowed_penetration;
  for (const JointMaterial& j : scene.joint_materials) {
    world.joint_laws.push_back(joint_law_of(j));
  }
  for (const JointSpec& j : scene.joints) world.pair_joint[pair_key(j.block_a, j.block_b)] = j.material;

  for (const PinSpec& pin : scene.pins) {
    world.pins.push_back(Pin{pin.block, pin.point, pin.point, pin.point});
  }
  for (const PointLoadSpec& load : scene.point_loads) {
    world.loads.push_back(PointLoad{load.block, load.point, load.point, load.force});
  }
  for (const BoltSpec& s : scene.bolts) {
    Bolt bolt;
    bolt.name = s.name;
    bolt.law = BoltLaw{s.stiffness, s.yield_force};
    bolt.rupture_extension = s.rupture_extension;
    bolt.force = s.pretension;
    world.bolts.push_back(bolt);
    world.bolt_ends.push_back(BoltEnd{s.block_from, s.from, s.from});
    world.bolt_ends.push_back(BoltEnd{s.block_to, s.to, s.to});
  }
  world.water = scene.water;
  world.base_motion = scene.base_motion;
  for (const MonitorSpec& m : scene.monitors) {
    world.monitors.push_back(Monitor{m.name, m.block, m.point, m.point});
  }
  start_energy_account(world);
  start_stages(world, scene);  // the first stage's settings, if the scene has stages
  return world;
}

void set_reaches(World& world, double dt) {
  const double k = world.control.dynamic_coefficient;  // a static step starts from rest
  const double fall = 0.5 * world.gravity.norm() * dt * dt;
  for (Block& b : world.blocks) {
    if (b.fixed) continue;
    const double translation = k * b.velocity.head<2>().norm() * dt + fall;
    b.reach = b.step_limit + kReachSafety * translation;
  }
}

int joint_of_contact(const World& world, int vertex_block, int edge_block, int edge) {
  const std::vector<int>& on_edge = world.blocks[static_cast<std::size_t>(edge_block)].edge_joints;
  if (!on_edge.empty() && on_edge[static_cast<std::size_t>(edge)] >= 0) {
    return on_edge[static_cast<std::size_t>(edge)];
  }
  return joint_of_pair(world, vertex_block, edge_block);
}

int joint_of_pair(const World& world, int i, int j) {
  const auto it = world.pair_joint.find(pair_key(i, j));
  return it == world.pair_joint.end() ? 0 : it->second;
}

double kinetic_energy(const World& world, const Block& block) {
  const Mat6 m = mass_matrix(shi_t(), block.moments, density_now(world, block));
  return 0.5 * block.velocity.dot(m * block.velocity);
}

}  // namespace dda
