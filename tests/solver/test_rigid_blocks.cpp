// Rigid blocks (docs/scene-format.md, "Rigid blocks"): three unknowns (u0, v0, r0) in the same
// system as deformable blocks. The rigid block's mass terms against the rigid body's own; a
// deformable block of growing stiffness against the rigid one (the same motion in the limit);
// rigid blocks under every rotation treatment; a mixed scene dropped into a box.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include "support/contact_scenes.hpp"
#include "kinematics/block_matrices.hpp"
#include "support/scene_builders.hpp"
#include "solver/energy.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"

using namespace dda;

namespace {

RunStats run_quietly(World& world) {
  return run(world, [](const World&, const RunStats&) { return true; });
}

// The vertices of block `b` after every step of a run (index: step).
std::vector<Polygon> trajectory(const Scene& scene, int b) {
  World w = make_world(scene);
  std::vector<Polygon> path;
  const RunStats stats = run(w, [&](const World& now, const RunStats&) {
    path.push_back(now.blocks[static_cast<std::size_t>(b)].vertices);
    return true;
  });
  INFO(stats.message);
  REQUIRE_FALSE(stats.diverged);
  REQUIRE(stats.cut_steps == 0);  // both runs take the same steps, compared step by step
  return path;
}

// The largest distance between corresponding vertices of two runs, over all their steps.
double largest_distance(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
  REQUIRE(a.size() == b.size());
  double largest = 0.0;
  for (std::size_t s = 0; s < a.size(); ++s) {
    for (std::size_t k = 0; k < a[s].size(); ++k) {
      largest = std::max(largest, (a[s][k] - b[s][k]).norm());
    }
  }
  return largest;
}

// The three motions of the convergence test; the moving block is the last one.
Scene thrown_spinning_bar() {
  Scene s = test::base_scene(200, 0.005);  // 1 s
  s.blocks.push_back(test::block(test::rectangle(-1.0, -0.25, 2.0, 0.5)));
  s.blocks[0].velocity = Vec3(1.0, 3.0, 2.0);  // thrown up, turning 2 rad in the second
  return s;
}

Scene pinned_bar() {
  Scene s = test::base_scene(200, 0.005);  // swings down through about 70 degrees
  s.blocks.push_back(test::block(test::rectangle(0.0, 0.0, 2.0, 0.5)));
  s.pins.push_back(PinSpec{{0.1, 0.25}, 0});
  return s;
}

Scene block_sliding_down_incline() {
  // 30 degree slope, friction 20 degrees: it slides at g (sin 30 - cos 30 tan 20).
  return test::block_on_incline(30.0, 20.0, 1.0, 0.5, 0.002, 0.5);
}

}  // namespace

TEST_CASE("rigid block: its mass terms are the rigid body's m, m, J (Shi's T about the "
          "centroid)", "[rigid]") {
  // The top-left 3x3 of int rho T^T T, T's columns u0, v0, r0 being (1, 0), (0, 1), (-Y, X)
  // (paper Eq. 3): diag(m, m, rho int (X^2 + Y^2)) since the first moments about the
  // centroid vanish. Closed forms: a rectangle a x b has J = m (a^2 + b^2) / 12, a right
  // triangle with legs a, b has J = m (a^2 + b^2) / 18. The integrals are exact polygon sums:
  // agreement to round-off (1e-12 relative).
  const double rho = 2700.0;
  const Polygon rectangle = test::rectangle(0.3, -0.2, 2.0, 0.5);
  const Polygon triangle{{0.0, 0.0}, {3.0, 0.0}, {0.0, 1.0}};
  for (const auto& [poly, m, j] :
       {std::tuple{rectangle, rho * 1.0, rho * 1.0 * (4.0 + 0.25) / 12.0},
        std::tuple{triangle, rho * 1.5, rho * 1.5 * (9.0 + 1.0) / 18.0}}) {
    const Mat6 mass = mass_matrix(shi_t(), polygon_moments(poly), rho);
    Mat3 expected = Mat3::Zero();
    expected.diagonal() << m, m, j;
    CHECK((mass.topLeftCorner<3, 3>() - expected).norm() <= 1e-12 * expected.norm());
  }
}

TEST_CASE("rigid block: a deformable block of growing stiffness moves as the rigid one in "
          "the limit", "[rigid]") {
  // The same scene with the block rigid, and deformable with E from 1e8 to 1e14 Pa (the
  // penalty of pins and contacts fixed at p = 1e8 N/m, so only the block's compliance
  // changes). The deformable equations tend to the rigid ones as E grows (their strain rows
  // are a penalty on the strain of stiffness A E), so the limit is the rigid motion itself.
  // A deformable block strains by about (its stress) / E and its motion differs from the
  // rigid one by as much: the largest vertex distance between the two runs, over the run,
  // falls about 100 times for each factor 100 in E once the block is stiffer than what
  // holds it (A E >> p; here from E = 1e10 on, A E >= 50 p).
  struct Case {
    const char* name;
    Scene scene;
  };
  for (const Case& c : {Case{"pinned, swinging", pinned_bar()},
                        Case{"sliding down an incline", block_sliding_down_incline()}}) {
    INFO("case: " << c.name);
    Scene base = c.scene;
    base.control.penalty = 1e8;
    const int moving = static_cast<int>(base.blocks.size()) - 1;
    Scene rigid = base;
    rigid.blocks.back().rigid = true;
    const std::vector<Polygon> reference = trajectory(rigid, moving);
    std::vector<double> distance;
    for (double young : {1e8, 1e10, 1e12, 1e14}) {
      Scene deformable = base;
      deformable.materials[0].parameters.young = young;
      distance.push_back(largest_distance(trajectory(deformable, moving), reference));
    }
    for (std::size_t k = 1; k < distance.size(); ++k) {
      INFO("E 1e" << 8 + 2 * (k - 1) << " -> 1e" << 8 + 2 * k << ": " << distance[k - 1]
                  << " -> " << distance[k] << " m");
      // Always at least as fast as 1/E, to within a factor 3; once A E >> p, 1/E itself
      // (0.01 a step) within a factor 2, which leaves room for the next order of the
      // expansion (measured: 0.0100 at every step for the pendulum; 0.0099 and 0.0100 on
      // the incline, whose first step, with A E = p / 2, gives 0.003).
      CHECK(distance[k] / distance[k - 1] < 0.03);
      if (k >= 2) CHECK(distance[k] / distance[k - 1] > 0.005);
      if (k >= 2) CHECK(distance[k] / distance[k - 1] < 0.02);
    }
    // At E = 1e14 Pa the stresses (~ rho g L = 5e4 Pa) strain the block by ~5e-10, about
    // 1e-9 m over its length: the motions agree within 1e-8 m over the whole run (measured
    // 2.2e-9 m swinging, 4.5e-10 m sliding).
    CHECK(distance.back() < 1e-8);
  }
}

TEST_CASE("rigid block: an unloaded spinning block moves as the rigid one at every "
          "stiffness", "[rigid]") {
  // Shi's step has no centrifugal term: with d = v0 dt the inertia terms of a steady spin,
  // M (2/dt^2 d - 2/dt v0), cancel in every row, the strain rows too, so under Shi's
  // inertia a free block thrown and spinning under gravity gets no strain at any E, and the
  // deformable block follows the rigid one to round-off (1e-13 m on 1 m coordinates over
  // 200 steps).
  Scene rigid = thrown_spinning_bar();
  rigid.blocks[0].rigid = true;
  const std::vector<Polygon> reference = trajectory(rigid, 0);
  for (double young : {1e8, 1e14}) {
    Scene deformable = thrown_spinning_bar();
    deformable.materials[0].parameters.young = young;
    deformable.control.inertia = Inertia::Shi;
    CHECK(largest_distance(trajectory(deformable, 0), reference) < 1e-13);
  }
}

TEST_CASE("rigid block: a spinning deformable block tends to the rigid one as E grows",
          "[rigid]") {
  // With the pseudo-rigid inertia (the default) the spin stretches the deformable block by
  // its centrifugal strain, about rho omega^2 L^2 / (12 E) along a side L, so its vertices
  // leave the rigid block's by about that strain times the half length, and the gap closes
  // in proportion to 1/E: the stiffer block's gap is 1e6 times smaller, within the
  // round-off floor of the test above (1e-13 m).
  Scene rigid = thrown_spinning_bar();
  rigid.blocks[0].rigid = true;
  const std::vector<Polygon> reference = trajectory(rigid, 0);
  double gap[2] = {0.0, 0.0};
  int k = 0;
  for (double young : {1e8, 1e14}) {
    Scene deformable = thrown_spinning_bar();
    deformable.materials[0].parameters.young = young;
    gap[k++] = largest_distance(trajectory(deformable, 0), reference);
  }
  INFO("gap at E 1e8: " << gap[0] << " m; at 1e14: " << gap[1] << " m");
  CHECK(gap[0] > 1e-9);  // a real centrifugal stretch, far above round-off
  CHECK(gap[1] < 1e-13 + 2e-6 * gap[0]);
}

TEST_CASE("rigid block: the rotation treatments move it rigidly, or as T with zero strain",
          "[rigid]") {
  // A rigid octagon spinning at 2 rad/s, 0.02 rad a step, no gravity. The treatments that
  // place it by an exact rotation (local frame, as printed: R(r)(I + 0); post-adjustment and
  // finite_rotation) keep every edge length and the area to round-off (1e-12 relative over
  // 100 steps); the first-order treatments move its vertices by T d with zero strain, as
  // they move a deformable block: `original` grows it by exactly 1 + r^2 a step and
  // `second_order` by 1 + r^4 / 4 (docs/scene-format.md).
  const double dt = 0.01, omega = 2.0;
  const RotationUpdate u =
      GENERATE(RotationUpdate::FiniteRotation, RotationUpdate::LocalFrame,
               RotationUpdate::LocalFrameAsPrinted, RotationUpdate::PostAdjustment,
               RotationUpdate::Original, RotationUpdate::SecondOrder);
  INFO("treatment " << rotation_update_name(u));
  Scene s = test::base_scene(100, dt);
  s.gravity = Vec2::Zero();
  s.control.rotation_update = u;
  s.control.energy_tolerance = std::numeric_limits<double>::infinity();  // original gains
  s.blocks.push_back(test::block(test::regular_polygon(8, 0.5)));
  s.blocks[0].velocity = Vec3(0.0, 0.0, omega);
  s.blocks[0].rigid = true;
  World w = make_world(s);
  const Polygon start = w.blocks[0].vertices;
  const double area0 = w.blocks[0].moments.area;
  double first_step_ratio = 0.0;
  run(w, [&](const World& now, const RunStats&) {
    if (now.step == 1) first_step_ratio = now.blocks[0].moments.area / area0;
    return true;
  });
  const Block& b = w.blocks[0];
  CHECK(b.strain == Vec3::Zero());
  CHECK(b.stress == Vec3::Zero());
  const double r = omega * dt;  // the steady spin's increment per step
  if (u == RotationUpdate::Original) {
    CHECK_THAT(first_step_ratio, Catch::Matchers::WithinRel(1.0 + r * r, 1e-12));
  } else if (u == RotationUpdate::SecondOrder) {
    CHECK_THAT(first_step_ratio, Catch::Matchers::WithinRel(1.0 + r * r * r * r / 4.0, 1e-12));
  } else {
    CHECK_THAT(b.moments.area, Catch::Matchers::WithinRel(area0, 1e-12));
    for (std::size_t k = 0; k < start.size(); ++k) {
      const std::size_t n = (k + 1) % start.size();
      CHECK_THAT((b.vertices[n] - b.vertices[k]).norm(),
                 Catch::Matchers::WithinRel((start[n] - start[k]).norm(), 1e-12));
    }
    CHECK_THAT(b.rotation, Catch::Matchers::WithinAbs(100 * r, 1e-9));
  }
}

namespace {

// Ten 0.25 m squares, turned by a few degrees, in two rows 0.35 m apart above the floor of a
// fixed box 1.5 m wide (as the hard case box5, verification/hard-cases), rigid and deformable
// in a checkerboard, so that rigid blocks land on deformable ones and the other way round.
Scene mixed_box() {
  Scene s = test::base_scene(0, 0.002);
  s.control.steps.reset();
  s.control.end_time = 1.0;
  s.control.max_displacement_ratio = 0.01;
  s.joint_materials[0].friction_angle = 30.0;
  for (const Polygon& wall : {test::rectangle(-0.2, -0.2, 1.9, 0.2),
                              test::rectangle(-0.2, 0.0, 0.2, 1.4),
                              test::rectangle(1.5, 0.0, 0.2, 1.4)}) {
    BlockSpec fixed = test::block(wall);
    fixed.fixed = true;
    s.blocks.push_back(fixed);
  }
  const double tilt[] = {-4.0, 3.0, -2.0, 5.0, 1.0, 2.0, -5.0, 4.0, -1.0, -3.0};
  for (int k = 0; k < 10; ++k) {
    const int row = k / 5, col = k % 5;
    const Vec2 c(0.3 * (col + 0.5), 0.3 + 0.125 + 0.35 * row);
    BlockSpec b = test::block(
        test::regular_polygon(4, 0.125 * std::sqrt(2.0), c, M_PI / 4 + tilt[k] * M_PI / 180.0));
    b.rigid = (row + col) % 2 == 0;
    s.blocks.push_back(b);
  }
  return s;
}

}  // namespace

TEST_CASE("rigid block: a mixed box keeps its energy account and its rigid blocks their "
          "shape", "[rigid]") {
  World w = make_world(mixed_box());
  std::vector<Polygon> start;
  for (const Block& b : w.blocks) start.push_back(b.vertices);
  const RunStats stats = run_quietly(w);
  INFO(stats.message);
  // The energy guard (control.energy_tolerance 0.02) would have stopped the run.
  REQUIRE_FALSE(stats.diverged);
  INFO("remainder max " << w.energy.remainder_max << " J/m of scale " << w.energy.scale);
  // The hard cases' bound: no gain beyond 1 % of the energy scale.
  CHECK(w.energy.remainder_max < 0.01 * w.energy.scale);
  // Rigid blocks store no strain energy: all of it is the deformable blocks'.
  double deformable_strain_energy = 0.0;
  for (const Block& b : w.blocks) {
    if (!b.fixed && !b.rigid) deformable_strain_energy += block_strain_energy(w, b);
  }
  CHECK(scene_energy(w).strain_energy == deformable_strain_energy);
  int rigid = 0, deformable = 0;
  for (std::size_t i = 0; i < w.blocks.size(); ++i) {
    const Block& b = w.blocks[i];
    if (b.fixed) continue;
    INFO("block " << i << (b.rigid ? " (rigid)" : " (deformable)"));
    // Every block has landed: dropped 0.3 m or more, its lowest vertex now below 0.45 m.
    double lowest = 1e9;
    for (const Vec2& v : b.vertices) lowest = std::min(lowest, v.y());
    CHECK(lowest < 0.45);
    if (b.rigid) {
      ++rigid;
      // Exactly zero strain and stress; shape kept to round-off (finite_rotation places it
      // by x = xc + R(r)(X - Xc): 1e-12 relative is a thousand ulps).
      CHECK(b.strain == Vec3::Zero());
      CHECK(b.local_strain == Vec3::Zero());
      CHECK(b.stress == Vec3::Zero());
      CHECK(block_strain_energy(w, b) == 0.0);
      CHECK_THAT(b.moments.area, Catch::Matchers::WithinRel(b.initial_area, 1e-12));
      for (std::size_t k = 0; k < b.vertices.size(); ++k) {
        const std::size_t n = (k + 1) % b.vertices.size();
        CHECK_THAT((b.vertices[n] - b.vertices[k]).norm(),
                   Catch::Matchers::WithinRel((start[i][n] - start[i][k]).norm(), 1e-12));
      }
    } else {
      ++deformable;
      // Loaded by its contacts, a deformable block does strain (far above round-off).
      CHECK(b.strain.cwiseAbs().maxCoeff() > 1e-9);
    }
  }
  CHECK(rigid == 5);
  CHECK(deformable == 5);
}
