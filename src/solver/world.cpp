#include "solver/world.hpp"

#include <algorithm>
#include <cassert>

#include "kinematics/block_matrices.hpp"
#include "materials/elastic.hpp"

namespace dda {
namespace {

// Shi's usual penalty: about 50 times the largest Young's modulus (per metre of thickness);
// see the verification catalogue ("Shi's usual controls").
constexpr double kAutoPenaltyFactor = 50.0;

double resolve_penalty(const Scene& scene) {
  if (scene.control.penalty) return *scene.control.penalty;
  double largest = 0.0;
  for (const Material& mat : scene.materials) largest = std::max(largest, mat.young);
  return kAutoPenaltyFactor * largest;
}

}  // namespace

World make_world(const Scene& scene) {
  World world;
  world.gravity = scene.gravity;
  world.plane = scene.plane;
  world.control = scene.control;
  world.penalty = resolve_penalty(scene);

  std::vector<Polygon> polygons;
  for (const BlockSpec& spec : scene.blocks) {
    const Material& mat = scene.materials.at(spec.material);
    Block b;
    b.initial_vertices = spec.vertices;
    b.vertices = spec.vertices;
    b.material = spec.material;
    b.fixed = spec.fixed;
    b.density = mat.density;
    b.elastic = elastic_matrix(mat.young, mat.poisson, scene.plane);
    b.initial_stress = spec.initial_stress;
    b.stress = spec.initial_stress;
    b.moments = polygon_moments(b.vertices);
    b.initial_area = b.moments.area;
    assert(b.moments.area > 0.0);
    if (!b.fixed) {
      b.first_dof = world.dof_count;
      world.dof_count += 6;
      b.velocity.head<3>() = spec.velocity;
    }
    world.blocks.push_back(std::move(b));
    polygons.push_back(spec.vertices);
  }

  const Box box = bounding_box(polygons);
  world.w0 = 0.5 * (box.max - box.min).maxCoeff();

  for (const PinSpec& pin : scene.pins) {
    world.pins.push_back(Pin{pin.block, pin.point, pin.point});
  }
  for (const PointLoadSpec& load : scene.point_loads) {
    world.loads.push_back(PointLoad{load.block, load.point, load.force});
  }
  return world;
}

double kinetic_energy(const Block& block) {
  const Mat6 m = mass_matrix(shi_t(), block.moments, block.density);
  return 0.5 * block.velocity.dot(m * block.velocity);
}

}  // namespace dda
