// Scene energy totals against closed forms.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/cli_helpers.hpp"
#include "support/contact_scenes.hpp"
#include "io/scene_reader.hpp"
#include "support/scene_builders.hpp"
#include "solver/configuration_update.hpp"
#include "solver/energy.hpp"
#include "solver/run.hpp"
#include "solver/step.hpp"
#include "solver/world.hpp"

using namespace dda;
using Catch::Matchers::WithinRel;

TEST_CASE("scene energy of a moving, strained block", "[energy]") {
  Scene s = test::base_scene(1, 0.01);
  s.blocks.push_back(test::block(test::rectangle(1.0, 2.0, 2.0, 1.0)));  // 2 m x 1 m, centroid (2, 2.5)
  s.blocks[0].velocity = Vec3(1.0, -2.0, 3.0);
  BlockSpec fixed = test::block(test::rectangle(-5.0, -5.0, 1.0, 1.0));
  fixed.fixed = true;  // fixed blocks carry no energy
  s.blocks.push_back(fixed);
  World w = make_world(s);
  w.blocks[0].strain = Vec3(1e-3, -2e-3, 5e-4);
  const EnergyTotals e = scene_energy(w);
  const double m = 2700.0 * 2.0;
  const double inertia = m * (4.0 + 1.0) / 12.0;  // rectangle about its centroid: m (a^2 + b^2) / 12
  // Kinetic: 1/2 m v^2 + 1/2 I omega^2 (no strain rates); potential: -m g . xc; strain:
  // area/2 e^T D e with plane-strain D (E = 1 GPa, nu = 0.25: lambda = 0.4 GPa, G = 0.4 GPa).
  const double lambda = 0.4e9, g = 0.4e9;
  const double ex = 1e-3, ey = -2e-3, gxy = 5e-4;
  const double w_strain = 0.5 * lambda * (ex + ey) * (ex + ey) + g * (ex * ex + ey * ey) + 0.5 * g * gxy * gxy;
  // Round-off only (a few operations on O(1) values): 1e-13 relative.
  CHECK_THAT(e.kinetic, WithinRel(0.5 * m * 5.0 + 0.5 * inertia * 9.0, 1e-13));
  CHECK_THAT(e.potential, WithinRel(m * 9.81 * 2.5, 1e-13));
  CHECK_THAT(e.strain_energy, WithinRel(2.0 * w_strain, 1e-13));
}

// ---- the energy account (solver/energy.hpp, docs/energy-balance.md) ----

namespace {

RunStats run_quietly(World& world) {
  return run(world, [](const World&, const RunStats&) { return true; });
}

double mass_of(const World& w, const Block& b) { return material_of(w, b).density * b.moments.area; }

}  // namespace

TEST_CASE("energy account: a constant point load's work is the kinetic energy it gives",
          "[energy]") {
  // A free block (no gravity) pushed by 1 kN at its centroid for 100 steps: Shi's step is
  // exact for a constant force (d = v0 dt + F/m dt^2/2), so K = F . x = load_work exactly.
  Scene s = test::base_scene(100, 0.01);
  s.gravity = Vec2::Zero();
  s.blocks.push_back(test::block(test::rectangle(0.0, 0.0, 1.0, 0.5)));
  s.point_loads.push_back(PointLoadSpec{{0.5, 0.25}, {1000.0, 0.0}, 0});
  World w = make_world(s);
  const double x0 = w.blocks[0].moments.centroid.x();
  REQUIRE_FALSE(run_quietly(w).diverged);
  const double work = 1000.0 * (w.blocks[0].moments.centroid.x() - x0);
  // Round-off of sums over 100 steps of O(1e3) J: 1e-9 relative.
  CHECK_THAT(w.energy.load_work, WithinRel(work, 1e-9));
  CHECK_THAT(scene_energy(w).kinetic, WithinRel(work, 1e-9));
  CHECK(std::abs(w.energy.remainder) < 1e-9 * work);
}

TEST_CASE("energy account: friction dissipates mu N times the distance slid", "[energy]") {
  // A 1 m x 0.5 m block sliding down a 30 degree slope with 20 degree friction: the joint
  // takes tan(20) m g cos(30) per metre slid (Coulomb), and what gravity gives beyond that
  // is kinetic energy, to the unexplained remainder.
  const Scene s = test::block_on_incline(30.0, 20.0, 1.0, 0.5, 0.001, 0.4);
  World w = make_world(s);
  const Vec2 c0 = w.blocks[1].moments.centroid;
  const double a = 30.0 * M_PI / 180.0;
  const Vec2 down(-std::cos(a), -std::sin(a));
  REQUIRE_FALSE(run_quietly(w).diverged);
  const double slid = (w.blocks[1].moments.centroid - c0).dot(down);
  const double m = mass_of(w, w.blocks[1]);
  const double expected = std::tan(20.0 * M_PI / 180.0) * m * 9.81 * std::cos(a) * slid;
  INFO("slid " << slid << " m, friction " << w.energy.friction_dissipation << " J/m, expected "
               << expected);
  REQUIRE(slid > 0.1);  // it does slide (0.5 g (sin 30 - tan 20 cos 30) t^2 = 0.15 m)
  // The normal force settles within the first steps from the penalty spring's initial
  // compression, while the block has hardly moved, so the transient costs little; what
  // remains is the block's elasticity (it squeezes and rocks on its springs): an error of
  // the order of its strain, m g / (b E) = 1.3e-5 for this 1 m wide block at 1 GPa. Measured
  // 9e-7 here (7.8e-6 and 8.9e-6 at dt 2 and 0.5 ms; a tenth at E = 10 GPa, the strain's
  // 1/E): three times the strain bounds it. (Formerly 1 %, 1e4 times the error.)
  const double strain = m * 9.81 / (1.0 * 1e9);
  CHECK_THAT(w.energy.friction_dissipation, WithinRel(expected, 3.0 * strain));
  // Unexplained: of the order of the block's elastic energy, the stress of its weight over
  // its width, (m g / b)^2 A / 2E = 0.044 J, 4.6e-5 of the potential energy released
  // (m g slid sin 30); measured 0.0118 J (1.24e-5 of it at every dt from 0.5 to 2 ms, a tenth
  // at E = 10 GPa). (Formerly 1e-3 of it, 80 times the remainder.)
  const double elastic = std::pow(m * 9.81 / 1.0, 2) * 0.5 / (2.0 * 1e9);
  INFO("remainder " << w.energy.remainder << " J, elastic energy scale " << elastic << " J");
  CHECK(std::abs(w.energy.remainder) < elastic);
}

TEST_CASE("energy account: a block dropped on a floor creates no energy", "[energy]") {
  // A 0.5 m square dropped 0.1 m onto a fixed floor, friction 30 degrees, dynamic; dt over a
  // factor 10. The impact's loss goes to damping; nothing may come out of nowhere.
  const double dt = GENERATE(0.002, 0.0002);
  const RotationUpdate rotation =
      GENERATE(RotationUpdate::FiniteRotation, RotationUpdate::FiniteRotationPolar);
  Scene s = test::base_scene(0, dt);
  s.control.rotation_update = rotation;
  s.control.steps.reset();
  s.control.end_time = 0.6;
  s.control.max_displacement_ratio = 0.01;
  s.joint_materials[0].friction_angle = 30.0;
  BlockSpec floor = test::block(test::rectangle(-1.0, -1.0, 3.0, 1.0));
  floor.fixed = true;
  s.blocks.push_back(floor);
  s.blocks.push_back(test::block(test::rectangle(0.2, 0.1, 0.5, 0.5)));
  World w = make_world(s);
  const double drop = mass_of(w, w.blocks[1]) * 9.81 * 0.1;
  const RunStats stats = run_quietly(w);
  INFO(stats.message << " dt " << dt << ", " << rotation_update_name(rotation)
                     << ", remainder max " << w.energy.remainder_max);
  REQUIRE_FALSE(stats.diverged);
  // The gain never exceeds round-off, and the block comes to rest on the floor. Round-off:
  // the account's terms are up to ~10 times the drop's energy (the potential energy from
  // y = 0 is 3.5 times it, the damping's sum about one), and at most 3000 steps each add a
  // few units of 1.1e-16 of them: ~1e-11 of the drop's energy if they all added up; 1e-9
  // (measured 3.4e-12 of it at dt 2 ms, 6.9e-13 at 0.2 ms). (Formerly 1e-3 of it,
  // for the re-detection jumps docs/energy-balance.md describes; this drop shows none.)
  // finite_rotation_polar (the default) commits the Hencky strain of the map the step
  // applied, ln U', where the step was linear in the strain increment de: the two differ
  // by de^2 / 2, and the account books s . (ln U' - ln U) for work s . de. At dt 2 ms the
  // impact strains the block by 4.4e-4 in one step at 5e5 Pa, A s de^2 / 2 ~ 0.012 J, 1.9e-5
  // of the drop's energy (measured 0.0123 J, at that one step; finite_rotation's account
  // is off by -0.0135 J there, a loss the gain check does not see). At 0.2 ms the impact
  // spreads over ten steps, each de ten times smaller: round-off (measured 4.5e-13 J).
  const double bound = rotation == RotationUpdate::FiniteRotationPolar && dt > 1e-3 ? 4e-5 : 1e-9;
  CHECK(w.energy.remainder_max < bound * drop);
  CHECK(scene_energy(w).kinetic < 1e-3 * drop);
  CHECK(w.energy.damping_dissipation > 0.5 * drop);
}

TEST_CASE("energy account: a block hanging from a bonded joint keeps its remainder",
          "[energy]") {
  // A 1 m x 0.5 m elastic block hangs under gravity from a wider fixed ceiling by a bonded
  // joint (tensile strength far above its weight), static steps (dynamic coefficient 0). Its
  // two top corners are contacts on the ceiling's edge, each in tension: at rest each carries
  // m g / 2 at a gap g = m g / (2 k) > 0, and their normal springs together hold
  // (m g)^2 / (4 k). Once the block is at rest nothing moves, nothing works and nothing
  // dissipates, so the remainder must stay where it is (a conservation law). The account
  // once counted a closed contact's start energy only while it penetrated and lost the
  // springs' (m g)^2 / (4 k) every step here: 45 steps, -0.039 J.
  Scene s = test::base_scene(50, 0.01);
  s.control.dynamic_coefficient = 0.0;
  s.joint_materials[0].cohesion = 1e8;
  s.joint_materials[0].tensile_strength = 1e8;
  BlockSpec ceiling = test::block(test::rectangle(-1.0, 0.0, 3.0, 1.0));
  ceiling.fixed = true;
  s.blocks.push_back(ceiling);
  s.blocks.push_back(test::block(test::rectangle(0.0, -0.5, 1.0, 0.5)));
  World w = make_world(s);
  const double weight = mass_of(w, w.blocks[1]) * 9.81;
  const double k = w.penalty;
  const double held = weight * weight / (4.0 * k);  // 8.8e-4 J
  StepWorkspace ws;
  RunStats stats;
  double at_rest = 0.0;  // the remainder once the block has settled
  for (int step = 1; step <= 50; ++step) {
    REQUIRE(advance_step(w, ws, stats).ok);
    if (step == 5) at_rest = w.energy.remainder;
  }
  int in_tension = 0;
  double normal = 0.0;  // the normal springs' energy
  for (const Contact& c : w.contacts) {
    if (c.state.mode == ContactMode::Open) continue;
    if (c.iterate.new_gap > 0.0) ++in_tension;
    normal += 0.5 * k * c.iterate.new_gap * c.iterate.new_gap;
  }
  REQUIRE(in_tension == 2);
  // The static equilibrium's closed form; the elastic block and the relaxation term of the
  // first steps leave 1e-8 of it (measured), the solve's round-off at k = 5e10 less.
  CHECK_THAT(normal, WithinRel(held, 1e-6));
  // Steps 6 to 50 change the remainder by round-off only: its terms are up to the potential
  // energy m g 0.25 = 3.3e3 J, and 45 steps of a few 1.1e-16 of that are ~1e-11 J (measured
  // 1.4e-12 J); 1e-6 of `held` is 9e-10 J, a thousandth of one step's former loss. The first
  // step, which takes the block from rest to its hanging shape, leaves 5e-8 J (its corners'
  // shear springs measured again on the contracted block), also far below `held`.
  INFO("remainder " << w.energy.remainder << " J, at step 5 " << at_rest << " J, springs hold "
                    << held << " J");
  CHECK(std::abs(w.energy.remainder - at_rest) < 1e-6 * held);
  CHECK(std::abs(w.energy.remainder) < 1e-3 * held);
}

TEST_CASE("energy account: plastic dissipation of a hardening Mohr-Coulomb soil is the integral "
          "of c d eps_p", "[energy]") {
  // scenes/plastic_column.json: associated Mohr-Coulomb, c = 20 kPa + 4 MPa eps_p. With
  // f = (s1 - s3) + (s1 + s3) sin phi - 2 c cos phi and d eps_p = 2 cos phi d lambda, the
  // dissipation s : d e_p = d lambda (f + 2 c cos phi) = c d eps_p, so over the run
  // D = A (c0 eps_p + 2e6 eps_p^2) with the final eps_p.
  const Scene scene = read_scene_file(std::string(DDA_SOURCE_DIR) + "/scenes/plastic_column.json");
  World w = make_world(scene);
  REQUIRE_FALSE(run_quietly(w).diverged);
  const Block& soil = w.blocks[1];
  const double ep = soil.material_state.eps_p;
  const double expected = soil.initial_area * (2.0e4 * ep + 2.0e6 * ep * ep);
  INFO("eps_p " << ep << ", plastic dissipation " << w.energy.plastic_dissipation);
  REQUIRE(ep > 1e-3);
  // The return takes c at the end of each step (backward Euler): the sum of c_end d eps_p
  // exceeds the integral by at most the cohesion's rise per step times eps_p, 1 % here.
  CHECK_THAT(w.energy.plastic_dissipation, WithinRel(expected, 0.02));
  // Its elastic strain energy is A/2 s : C^-1 : s (plastic strain excluded), well below the
  // energy of the total strain (which counted plastic strain 2.6 times too high before).
  const Vec4 sig(soil.stress[0], soil.stress[1], soil.szz, soil.stress[2]);
  const double e = 5.0e7, nu = 0.3;
  const double density = (sig[0] * sig[0] + sig[1] * sig[1] + sig[2] * sig[2] -
                          2 * nu * (sig[0] * sig[1] + sig[1] * sig[2] + sig[2] * sig[0]) +
                          2 * (1 + nu) * sig[3] * sig[3]) / (2 * e);
  // (Over the area the stress acts on: the initial one under the default
  // finite_rotation_polar, whose stress is Kirchhoff's; configuration_update.hpp.)
  CHECK_THAT(block_strain_energy(w, soil),
             WithinRel(stress_area(w.control.rotation_update, soil) * density, 1e-12));
}

TEST_CASE("energy account: a scene at rest has a floor under its energy scale, and runs",
          "[energy]") {
  // A 2 m x 0.5 m bar pinned near one end, with no gravity, no load and no velocity: its
  // energy scale was 0, and the round-off of its first step (1.9e-23 J/m) "inf %" of it, so
  // the guard stopped it at step 1. The floor is the strain energy of the free blocks at a
  // strain of 1e-6: E A (1e-6)^2 / 2 = 1e9 x 1 x 1e-12 / 2 = 5e-4 J/m.
  Scene s = test::base_scene(20, 0.005);
  s.gravity = Vec2::Zero();
  s.blocks.push_back(test::block(test::rectangle(0.0, 0.0, 2.0, 0.5)));
  BlockSpec fixed = test::block(test::rectangle(-5.0, -5.0, 1.0, 1.0));
  fixed.fixed = true;  // adds nothing to the floor
  s.blocks.push_back(fixed);
  PinSpec pin;
  pin.point = Vec2(0.1, 0.25);
  pin.block = 0;
  s.pins.push_back(pin);
  World w = make_world(s);
  CHECK_THAT(w.energy.scale, WithinRel(0.5 * 1e9 * 1.0 * kRestScaleStrain * kRestScaleStrain, 1e-12));
  const RunStats stats = run_quietly(w);
  INFO(stats.message);
  CHECK_FALSE(stats.diverged);
  CHECK(stats.steps == 20);
  // The remainder stays round-off, far below the floor (2 % of it would stop the run).
  CHECK(std::abs(w.energy.remainder) < 1e-12 * w.energy.scale);
  CHECK(energy_guard_message(w, StepEnergy{}, w.control.energy_tolerance).empty());

  // A scene that moves keeps its own scale: the floor is far below m g w0.
  Scene falling = s;
  falling.gravity = Vec2(0.0, -9.81);
  const World f = make_world(falling);
  CHECK(f.energy.scale > 1e6 * 0.5 * 1e9 * kRestScaleStrain * kRestScaleStrain);
}

TEST_CASE("energy guard: a run that creates energy stops with exit 3 and says so", "[energy][cli]") {
  // scenes/pendulum.json under post_adjustment (Ke; Koo and Chern): the rigid rotation of the
  // update does not match Shi's linear T inside the step and the pinned bar gains about 2 %
  // of its energy scale in 0.23 s (the paper reproduction shows the same gain). The guard
  // (control.energy_tolerance, default 0.02) stops it; a larger tolerance lets it run.
  dda::test::TempDir dir("energy_guard");
  std::string scene = dda::test::read_file(std::string(DDA_SOURCE_DIR) + "/scenes/pendulum.json");
  const std::string key = "\"control\": {";
  const auto at = scene.find(key);
  REQUIRE(at != std::string::npos);
  scene.replace(at, key.size(), key + "\"rotation_update\": \"post_adjustment\", ");
  // Writes the scene as NAME.json and runs it into NAME/.
  auto run_scene = [&](const std::string& name) {
    dda::test::write_file(dir.path / (name + ".json"), scene);
    return dda::test::run_command(std::string(DDA_EXE) + " run " +
                                  (dir.path / (name + ".json")).string() + " --out " +
                                  (dir.path / name).string());
  };
  const dda::test::CommandResult c = run_scene("gains");
  INFO(c.output);
  CHECK(c.exit_code == 3);
  CHECK(dda::test::contains(c.output, "gained without a cause"));
  CHECK(dda::test::contains(c.output, "energy_tolerance"));
  // What was written up to the stop is kept, and the summary says why.
  const std::string summary = dda::test::read_file(dir.path / "gains" / "summary.json");
  CHECK(dda::test::contains(summary, "\"diverged\": true"));

  scene.replace(scene.find(key), key.size(), key + "\"energy_tolerance\": 1000, ");
  const dda::test::CommandResult d = run_scene("allowed");
  INFO(d.output);
  CHECK(d.exit_code == 0);
}

TEST_CASE("energy guard: energy lost without a cause is reported, and stops the run when asked",
          "[energy][cli]") {
  // Two 0.25 m squares meeting head on at 1 m/s each, no gravity, dt 0.0002 s (the hard case
  // collision-dynamic-dt0.0002): the account loses 1.86 J/m, 1.10 % of the initial kinetic
  // energy (168.75 J/m; 1.90 J/m before the spatial inertia), at step 254, the step the
  // contact opens, and no term books it. The tolerances below are chosen on either side of that loss with
  // room for the loss to move by a factor of two: at the default 0.02 it is not reported as
  // beyond; at 0.005 it is, and with energy_losses "stop" the run stops with exit 3 there.
  dda::test::TempDir dir("energy_losses");
  auto scene = [](const std::string& extra) {
    return std::string(R"({
  "gravity": [0, 0],
  "control": {"time_step": 0.0002, "end_time": 0.1, "dynamic_coefficient": 1)") + extra +
           R"(},
  "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
  "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
  "blocks": [
    {"vertices": [[-0.3, -0.125], [-0.05, -0.125], [-0.05, 0.125], [-0.3, 0.125]], "material": "rock", "velocity": [1, 0, 0]},
    {"vertices": [[0.05, -0.125], [0.3, -0.125], [0.3, 0.125], [0.05, 0.125]], "material": "rock", "velocity": [-1, 0, 0]}
  ]
})";
  };
  auto run_scene = [&](const std::string& name, const std::string& extra) {
    dda::test::write_file(dir.path / (name + ".json"), scene(extra));
    return dda::test::run_command(std::string(DDA_EXE) + " run " +
                                  (dir.path / (name + ".json")).string() + " --out " +
                                  (dir.path / name).string());
  };
  auto energy_of = [&](const std::string& name) {
    return nlohmann::json::parse(dda::test::read_file(dir.path / name / "summary.json"))["energy"];
  };

  const dda::test::CommandResult quiet = run_scene("default", "");
  INFO(quiet.output);
  REQUIRE(quiet.exit_code == 0);
  const nlohmann::json e = energy_of("default");
  const double share = e["remainder_min_share"].get<double>();
  INFO("loss share " << share);
  CHECK(share < -0.005);
  CHECK(share > -0.02);
  CHECK(e["remainder_min_step"].get<int>() > 0);
  CHECK_FALSE(e["losses_beyond_tolerance"].get<bool>());
  CHECK_FALSE(dda::test::contains(quiet.output, "no term books"));

  const dda::test::CommandResult reported = run_scene("report", R"(, "energy_tolerance": 0.005)");
  INFO(reported.output);
  CHECK(reported.exit_code == 0);
  CHECK(dda::test::contains(reported.output, "warning: the energy account lost"));
  CHECK(dda::test::contains(reported.output, "no term books"));
  CHECK(energy_of("report")["losses_beyond_tolerance"].get<bool>());

  const dda::test::CommandResult stopped =
      run_scene("stop", R"(, "energy_tolerance": 0.005, "energy_losses": "stop")");
  INFO(stopped.output);
  CHECK(stopped.exit_code == 3);
  CHECK(dda::test::contains(stopped.output, "lost without a cause"));
  const nlohmann::json summary =
      nlohmann::json::parse(dda::test::read_file(dir.path / "stop" / "summary.json"));
  CHECK(summary["diverged"].get<bool>());
  CHECK(summary["settings"]["energy_losses"] == "stop");
  // It stops at the step whose loss first passed the tolerance: the step the contact opens,
  // where the full run's loss is already beyond it. Its deepest point is a few steps on at
  // most: the same step under finite_rotation, one later under finite_rotation_polar with
  // the Hencky rates as velocities, two later (254 and 256; loss 1.86 J/m, 1.10 %) with
  // the spatial inertia (kinematics/rotating_inertia.hpp).
  const int stop_step = summary["steps"].get<int>();
  CHECK(stop_step <= e["remainder_min_step"].get<int>());
  CHECK(stop_step >= e["remainder_min_step"].get<int>() - 2);
}

TEST_CASE("energy account: a Mohr-Coulomb block that never yields books no plastic work",
          "[energy][plastic]") {
  // A 1 m quadrilateral thrown spinning (3 rad/s) onto a floor, dynamic, 2 s, once of an
  // elastic material and once of a Mohr-Coulomb one too strong to yield (c = 100 MPa
  // against impact stresses near 1 MPa). Its plastic work must be zero at every step, and
  // its account the elastic block's. Read in the global frame, the increment d[ex..] and
  // the stresses turned by the start and end angles booked -6.1 J of plastic work (and
  // the change of the block's area with its strain another share): measured now 1e-13 J,
  // round-off of 1000 steps of terms near 1e4 J. Bound 1e-9 J: a tenth of a
  // nanojoule, far below the 6 J the frame error booked. The two runs' remainders
  // (-34.11 J, the impacts' unbooked loss) agree to 1e-3 J, 3e-5 of them: the trajectories
  // part at round-off through the impacts; bound 1e-3 of the remainder (except the polar
  // treatment, below).
  auto scene = [](const std::string& soil, const std::string& treatment) {
    return parse_scene_text(std::string(R"({
      "gravity": [0, -9.81],
      "control": {"time_step": 0.002, "end_time": 2, "dynamic_coefficient": 1, "rotation_update": ")") +
                                treatment + R"("},
      "materials": {"soil": )" + soil + R"(,
        "rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25}},
      "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0}},
      "blocks": [
        {"vertices": [[-1, -1], [6, -1], [6, 0], [-1, 0]], "material": "rock", "fixed": true},
        {"vertices": [[0, 0.3], [1, 0.1], [1.2, 1.1], [0.2, 1.3]], "material": "soil", "velocity": [2, 0, 3]}
      ]
    })", "spin.json");
  };
  const std::string elastic = R"({"model": "elastic", "density": 2000, "young": 5e7, "poisson": 0.3})";
  const std::string strong = R"({"model": "mohr_coulomb", "density": 2000, "young": 5e7, "poisson": 0.3,
                                 "cohesion": 1e8, "friction_angle": 30, "tensile_strength": 1e8})";
  for (const char* treatment : {"finite_rotation", "finite_rotation_polar", "original"}) {
    INFO(treatment);
    World e = make_world(scene(elastic, treatment));
    REQUIRE_FALSE(run_quietly(e).diverged);
    World p = make_world(scene(strong, treatment));
    double worst = 0.0;
    const RunStats stats = run(p, [&](const World& w, const RunStats&) {
      worst = std::max(worst, std::abs(w.energy.plastic_dissipation));
      return true;
    });
    REQUIRE_FALSE(stats.diverged);
    INFO("plastic work at most " << worst << " J; remainders " << p.energy.remainder << " and "
                                 << e.energy.remainder << " J");
    CHECK(worst < 1e-9);
    // finite_rotation_polar's plastic blocks follow their material through its Newton
    // iteration with a tangent that is not yet the polar strain's (docs/
    // polar-placement-prototype.md): their remainder, -37.33 J, is not the elastic
    // block's -39.57 J. The plastic work is zero there too.
    if (std::string(treatment) != "finite_rotation_polar") {
      CHECK(std::abs(p.energy.remainder - e.energy.remainder) < 1e-3 * std::abs(e.energy.remainder));
    }
  }
}

namespace {

// A plastic block in an impact, run under the default treatment: the
// largest gain and loss of its energy account, the least plastic dissipation a step
// booked, the plastic dissipation at the end and the kinetic energy left.
struct ImpactRun {
  bool diverged = false;
  std::string message;
  double gain = 0.0, loss = 0.0, scale = 0.0;
  double least_plastic_step = 0.0;
  double plastic = 0.0;
  double kinetic_end = 0.0;
};

ImpactRun run_impact(const std::string& blocks, const std::string& soil, double dynamic,
                     double dt, double end_time, double joint_friction) {
  std::ostringstream text;
  text << R"({"gravity": [0, -9.81], "plane": "strain",
    "control": {"time_step": )" << dt << R"(, "end_time": )" << end_time
       << R"(, "dynamic_coefficient": )" << dynamic << R"(},
    "materials": {"rock": {"model": "elastic", "density": 2700, "young": 1e9, "poisson": 0.25},
                  "weight": {"model": "elastic", "density": 20000, "young": 1e9, "poisson": 0.25},
                  "soil": )" << soil << R"(},
    "joint_materials": {"default": {"friction_angle": )" << joint_friction
       << R"(, "cohesion": 0, "tensile_strength": 0}},
    "blocks": [{"vertices": [[-1, -1], [3, -1], [3, 0], [-1, 0]], "material": "rock", "fixed": true}, )"
       << blocks << "]}";
  World w = make_world(parse_scene_text(text.str(), "impact.json"));
  ImpactRun out;
  double plastic_before = 0.0;
  out.least_plastic_step = std::numeric_limits<double>::infinity();
  const RunStats stats = run(w, [&](const World& now, const RunStats&) {
    out.least_plastic_step =
        std::min(out.least_plastic_step, now.energy.plastic_dissipation - plastic_before);
    plastic_before = now.energy.plastic_dissipation;
    return true;
  });
  out.diverged = stats.diverged;
  out.message = stats.message;
  out.gain = w.energy.remainder_max;
  out.loss = w.energy.remainder_min;
  out.scale = w.energy.scale;
  out.plastic = w.energy.plastic_dissipation;
  out.kinetic_end = scene_energy(w).kinetic;
  return out;
}

// c = 2 kPa, phi 30, psi 0, tension cut-off 0: yields on impact, never in tension.
constexpr const char* kWeakSoil =
    R"({"model": "mohr_coulomb", "density": 2000, "young": 5e7, "poisson": 0.3, "cohesion": 2000,
        "friction_angle": 30, "dilation_angle": 0, "tensile_strength": 0})";
// scenes/plastic_column.json's soil: c = 20 kPa hardening to 60 kPa at eps_p 0.01,
// associated (phi = psi = 30): under the 98.1 kPa weight it yields and hardens until
// 2 c sqrt(N) carries it.
constexpr const char* kHardeningSoil =
    R"({"model": "mohr_coulomb", "density": 20, "young": 5e7, "poisson": 0.3, "cohesion": 2e4,
        "friction_angle": 30, "dilation_angle": 30, "hardening": [[0, 2e4], [0.01, 6e4]]})";

}  // namespace

TEST_CASE("energy account: plastic blocks in impacts come to rest with plastic dissipation "
          "that never falls and an account that closes",
          "[energy][plastic]") {
  // Under the default finite_rotation_polar (docs/large-strain.md); each case yields (its
  // plastic dissipation ends above zero). Bounds, against the run's energy scale, are about
  // three times what was measured: the gains are the Hencky strain's
  // second-order term of the steps with the largest strain increments (the impacts), the
  // loss is the wall's, a contact solved open over the step it opens in
  // (docs/energy-balance.md, "Losses"). A step's plastic dissipation falls below zero by
  // round-off only (measured at most 2e-12 J against thousands booked; bound 1e-9 of the
  // scale).
  struct Case {
    const char* name;
    std::string blocks;
    const char* soil;
    double dynamic, dt, end_time, joint_friction;
    double gain_bound, loss_bound;  // shares of the scale
  };
  const Case cases[] = {
      // Dropped 0.1 m: gain 2.92 J/m of 39 240 (7.4e-5), loss 0.95 J/m (2.4e-5), since the
      // default's inertia is spatial (kinematics/rotating_inertia.hpp; before: 1.87 and
      // 0.15 J/m). The loss is the impact's and moves a lot with dt under either inertia
      // (25 J/m at dt 0.001, 2.2 J/m at 0.0005): a bound for this dt, not a trend.
      {"dropped 0.1 m", R"({"vertices": [[0, 0.1], [1, 0.1], [1, 1.1], [0, 1.1]], "material": "soil"})",
       kWeakSoil, 1.0, 0.002, 1.0, 30.0, 1.5e-4, 7.5e-5},
      // Thrown at 3 m/s against a fixed wall 0.5 m away, standing on the floor: gain 4.97
      // J/m (1.27e-4), loss 2.07 J/m (5.3e-5). The gain builds up while the block slides
      // on the floor before the impact, its base friction shearing it plastically (12 J/m
      // of flow a step, 0.1 to 0.2 J/m of gain: the linear step's second-order term,
      // docs/large-strain.md section 3; 3.18 J/m at dt 0.001, 0.41 at 0.0005). Until
      // attempts ending with contacts solved open inside their edge's block were no longer
      // accepted (step.cpp, kAcceptedInsideShare) twenty such attempts were accepted and
      // then cut for overshoot, and the slide ran at smaller steps: gain 0.82 J/m, loss
      // 108 J/m as it rebounded.
      {"thrown against a wall",
       R"({"vertices": [[2, 0], [3, 0], [3, 2], [2, 2]], "material": "rock", "fixed": true},
          {"vertices": [[0.5, 0], [1.5, 0], [1.5, 1], [0.5, 1]], "material": "soil", "velocity": [3, 0, 0]})",
       kWeakSoil, 1.0, 0.002, 1.5, 30.0, 3e-4, 7.5e-3},
      // Crushed by a 98.1 kN/m block set on it with gravity at once, frictionless joints,
      // dynamic: gain 0.12 J/m of 196 592 (6.1e-7); static: 0.0125 J/m (6.4e-8).
      {"crushed, dynamic",
       R"({"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "soil"},
          {"vertices": [[0, 1], [1, 1], [1, 1.5], [0, 1.5]], "material": "weight"})",
       kHardeningSoil, 1.0, 0.002, 3.0, 0.0, 2e-6, 1e-9},
      {"crushed, static",
       R"({"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "material": "soil"},
          {"vertices": [[0, 1], [1, 1], [1, 1.5], [0, 1.5]], "material": "weight"})",
       kHardeningSoil, 0.0, 0.01, 3.0, 0.0, 2e-7, 1e-9},
  };
  for (const Case& c : cases) {
    const ImpactRun r = run_impact(c.blocks, c.soil, c.dynamic, c.dt, c.end_time, c.joint_friction);
    INFO(c.name << ": " << r.message << "; gain " << r.gain << ", loss " << r.loss << " of scale "
                << r.scale << "; plastic " << r.plastic << " (least step "
                << r.least_plastic_step << "); kinetic at the end " << r.kinetic_end);
    REQUIRE_FALSE(r.diverged);
    CHECK(r.plastic > 1.0);  // it yielded (J/m; 5.7 to 1570 measured)
    CHECK(r.least_plastic_step >= -1e-9 * r.scale);
    CHECK(r.gain <= c.gain_bound * r.scale);
    CHECK(r.loss >= -c.loss_bound * r.scale);
    // At rest: what still moves at the end is below 1e-6 of the scale, a criterion, not an
    // error bound (measured at most 4e-10).
    CHECK(r.kinetic_end <= 1e-6 * r.scale);
  }
}
