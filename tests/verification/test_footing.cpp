// Plasticity in a boundary-value problem (verification/footing): a smooth
// rigid strip footing pressed into a weightless Tresca layer of 128 constant-strain
// triangular blocks (the coarsest mesh of the refinement study, cell h = b / 2) against
// Prandtl's bearing pressure (2 + pi) c.
#include <catch2/catch.hpp>
#include <cmath>

#include "footing_case.hpp"

using namespace dda;
using namespace dda::footing;

TEST_CASE("Prandtl's bearing capacity factors", "[footing]") {
  CHECK(prandtl_pressure(1.0, 0.0) == Approx(2.0 + M_PI).epsilon(1e-15));
  // Textbook N_c (Prandtl-Reissner; e.g. Terzaghi, Peck and Mesri, Table 33.1): 14.83 at
  // 20 degrees, 30.14 at 30 degrees; and N_c tends to 2 + pi as phi tends to 0.
  CHECK(prandtl_pressure(1.0, 20.0) == Approx(14.83).epsilon(1e-3));
  CHECK(prandtl_pressure(1.0, 30.0) == Approx(30.14).epsilon(1e-3));
  CHECK(prandtl_pressure(1.0, 1e-6) == Approx(2.0 + M_PI).epsilon(1e-6));
}

TEST_CASE("a rigid strip footing on a Tresca layer of blocks reaches Prandtl's load from above",
          "[footing][plastic]") {
  FootingCase c;  // h = 0.5 m: 128 blocks, b = 1 m, pushed 6 cm (s / B = 3 %)
  // 30 steps of 2 mm: the study's 150 and 300 steps of this mesh end at q / c = 6.4192 and
  // 6.4186, 30 steps at 6.423: the load step changes the limit pressure by 0.06 %.
  c.steps = 30;
  const FootingResult r = run_footing(c);
  INFO(r.message);
  REQUIRE(r.ok);
  REQUIRE(r.curve.size() == static_cast<std::size_t>(c.steps) + 1);
  const double qu = prandtl_pressure(c.cohesion, c.friction_angle);
  const double q = r.final_pressure;
  INFO("q / c " << q / c.cohesion << ", Prandtl " << qu / c.cohesion << ", error " << q / qu - 1.0);

  // The mesh holds together: every contact between two blocks that share an edge stays
  // bonded and locked at every step (the plasticity is in the blocks, not the joints). Their
  // corners meet vertex to vertex, a contact whose key changes with round-off; before the
  // bond was handed over with it (contact/carry_over.cpp) half of them were lost by step 20
  // and the layer carried less than Prandtl's load.
  const int edge_contacts = r.curve[1].edge_locked;
  CHECK(edge_contacts == 360);  // 180 shared edges, a contact at each end
  for (const CurvePoint& p : r.curve) {
    if (p.step == 0) continue;
    INFO("step " << p.step);
    CHECK(p.edge_locked == edge_contacts);
    CHECK(p.edge_unbonded == 0);
  }

  // The limit pressure lies above Prandtl's: the blocks' displacement fields (constant
  // strain, bonded at the corners) are a constrained subset of the soil's, so with
  // associated flow the mesh's collapse load bounds the exact one from above (Prandtl's
  // mechanism fits inside this layer, so the exact load is (2 + pi) c), and constant-strain
  // blocks stiffen further under isochoric flow (locking, eased but not removed by the
  // crossed diagonals). The refinement study (verification/footing/README.md) measured
  // +24.8 % on this mesh at 150 steps, +14.6 % at h = 0.25 m and +8.6 % at h = 0.125 m
  // (order 0.77 in h; Richardson's extrapolation gives 5.139 c, -0.05 % from Prandtl; those
  // under finite_rotation). The result is deterministic: this mesh at the test's 30 steps
  // gives +26.36 % under the default finite_rotation_polar (q / c = 6.497; its Kirchhoff
  // stress over the initial area and Hencky strain, docs/large-strain.md) where
  // finite_rotation gave +24.94 % (6.4240) while losing 1113 J/m over the study's 150 steps
  // that no term booked; the study's 150 steps give 6.4954 (polar), so the load step moves
  // it by 0.03 %. The band, +26.36 % +- 0.5 % of q_u (15 times that), lets the load step,
  // the penalty and the solver's tolerances move it and catches any change of the method's
  // answer.
  CHECK(q > qu);
  CHECK(q / qu - 1.0 == Approx(0.2636).margin(0.005));

  // The load has levelled off: over the last third of the push the curve's slope is within
  // 5 % of its initial (elastic) slope, and it does not soften beyond 1 % of it. Measured:
  // -0.1 % (0.8 % while point contacts between triangles that meet only
  // at a mesh node still carried half a face of bond each: contact/narrow_phase.hpp,
  // face_shares).
  const CurvePoint& first = r.curve[1];
  const CurvePoint& two_thirds = r.curve[static_cast<std::size_t>(2 * c.steps / 3)];
  const CurvePoint& last = r.curve.back();
  const double initial_slope = first.pressure / first.settlement;
  const double final_slope = (last.pressure - two_thirds.pressure) / (last.settlement - two_thirds.settlement);
  INFO("final slope / initial slope " << final_slope / initial_slope);
  CHECK(final_slope >= -0.01 * initial_slope);
  CHECK(final_slope < 0.05 * initial_slope);

  // A mechanism, not a crushed column: the soil has yielded beside the footing, at the
  // surface between b and 3 b where Prandtl's passive wedge comes up.
  int beside = 0;
  for (std::size_t k = 0; k < r.zone.polygons.size(); ++k) {
    const Vec2 centre = polygon_moments(r.zone.polygons[k]).centroid;
    if (centre.y() > -0.5 * c.cell && centre.x() > c.half_width && centre.x() < 3.0 * c.half_width &&
        r.zone.eps_p[k] > 0.0) {
      ++beside;
    }
  }
  CHECK(beside > 0);
}
