// Checkpoints (io/checkpoint.hpp): a world written and read back is the same world bit for
// bit, field by field (the comparison below lists World's fields itself, apart from the
// serializer, so a field the serializer misses shows here), and a run stopped at step k and
// continued from its checkpoint ends exactly where the run in one piece ends.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "io/checkpoint.hpp"
#include "io/input_error.hpp"
#include "io/scene_reader.hpp"
#include "solver/run.hpp"
#include "solver/step.hpp"
#include "support/checkpoint_scene.hpp"

namespace {

using namespace dda;


bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <class M>
bool same_bits(const M& a, const M& b) {
  if (a.size() != b.size()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    if (!same_bits(a.data()[i], b.data()[i])) return false;
  }
  return true;
}

bool same_bits(const Polygon& a, const Polygon& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same_bits(a[i], b[i])) return false;
  }
  return true;
}

#define SAME(x) CHECK(same_bits(a.x, b.x))
#define EQUAL(x) CHECK(a.x == b.x)

void require_same(const JointLaw& a, const JointLaw& b) {
  SAME(tan_phi); SAME(cohesion); SAME(tensile_strength); EQUAL(kind); SAME(residual_tan_phi);
  SAME(residual_cohesion); SAME(residual_slip); SAME(jrc); SAME(jcs); SAME(friction_divisor);
}

void require_same(const ControlSettings& a, const ControlSettings& b) {
  EQUAL(time_steps); EQUAL(steps); EQUAL(end_time); SAME(max_displacement_ratio);
  SAME(dynamic_coefficient); EQUAL(rotation_update); EQUAL(penalty); EQUAL(output_every);
  EQUAL(vtk_binary); EQUAL(max_open_close); EQUAL(max_augmentations); EQUAL(reuse_factor);
  EQUAL(allowed_penetration); SAME(energy_tolerance); EQUAL(stop_on_energy_loss);
  EQUAL(contact_solver); EQUAL(inertia);
}

void require_same(const Block& a, const Block& b) {
  SAME(initial_vertices); SAME(initial_centroid); EQUAL(material); EQUAL(fixed); EQUAL(edge_joints);
  REQUIRE(a.edge_bridges.size() == b.edge_bridges.size());
  for (std::size_t i = 0; i < a.edge_bridges.size(); ++i) {
    CHECK(a.edge_bridges[i].material == b.edge_bridges[i].material);
    CHECK(same_bits(a.edge_bridges[i].share, b.edge_bridges[i].share));
  }
  SAME(initial_stress); SAME(initial_area); SAME(material_inertia); EQUAL(first_dof);
  EQUAL(excavated); SAME(step_limit); SAME(reach); SAME(size); EQUAL(rigid); EQUAL(plastic);
  SAME(vertices); SAME(moments.area); SAME(moments.centroid); SAME(moments.sxx); SAME(moments.syy);
  SAME(moments.sxy); SAME(translation); SAME(rotation); SAME(strain); SAME(local_strain);
  SAME(stress); SAME(velocity); SAME(local_strain_rate); SAME(last_rotation_increment);
  SAME(last_local_increment); SAME(material_state.plastic_strain); SAME(material_state.eps_p);
  SAME(szz); EQUAL(branch);
}

void require_same(const Contact& a, const Contact& b) {
  EQUAL(key); EQUAL(joint); EQUAL(bridge_joint); SAME(bridge_share); SAME(start_normal_force);
  SAME(vertex); SAME(edge_start); SAME(edge_end); SAME(tangent); SAME(normal); SAME(gap); SAME(t);
  SAME(length); SAME(allowed_penetration);
  EQUAL(state.mode); EQUAL(state.slide_sign); SAME(state.t_lock); EQUAL(state.bonded);
  SAME(state.predicted_slip); SAME(state.normal_force); SAME(state.rest_shift);
  SAME(state.spring_energy); SAME(state.slip_sum);
  REQUIRE(a.state.deferred.has_value() == b.state.deferred.has_value());
  if (a.state.deferred) {
    CHECK(a.state.deferred->mode == b.state.deferred->mode);
    CHECK(a.state.deferred->slide_sign == b.state.deferred->slide_sign);
    CHECK(a.state.deferred->relock == b.state.deferred->relock);
    CHECK(same_bits(a.state.deferred->lock_offset, b.state.deferred->lock_offset));
  }
  SAME(iterate.new_gap); SAME(iterate.shear_force); SAME(iterate.slip); EQUAL(iterate.mode_changes);
  EQUAL(iterate.start_mode); SAME(iterate.start_t_lock);
}

// Every field of World and of what it holds, doubles bit for bit.
void require_same(const World& a, const World& b) {
  REQUIRE(a.materials.size() == b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    const MaterialParameters& p = a.materials[i].parameters;
    const MaterialParameters& q = b.materials[i].parameters;
    CHECK(same_bits(p.young, q.young));
    CHECK(same_bits(p.poisson, q.poisson));
    CHECK(same_bits(p.density, q.density));
    CHECK(p.plane == q.plane);
    REQUIRE(p.model() == q.model());
    if (const FrictionalStrength* f = frictional_strength(p)) {
      const FrictionalStrength* g = frictional_strength(q);
      CHECK(same_bits(f->cohesion, g->cohesion));
      CHECK(same_bits(f->friction_angle, g->friction_angle));
      CHECK(same_bits(f->dilation_angle, g->dilation_angle));
      REQUIRE(f->hardening.size() == g->hardening.size());
      for (std::size_t k = 0; k < f->hardening.size(); ++k) {
        CHECK(same_bits(f->hardening[k].eps_p, g->hardening[k].eps_p));
        CHECK(same_bits(f->hardening[k].cohesion, g->hardening[k].cohesion));
      }
    }
    CHECK(same_bits(a.materials[i].elastic, b.materials[i].elastic));
  }
  REQUIRE(a.blocks.size() == b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    INFO("block " << i);
    require_same(a.blocks[i], b.blocks[i]);
  }
  REQUIRE(a.pins.size() == b.pins.size());
  for (std::size_t i = 0; i < a.pins.size(); ++i) {
    CHECK(a.pins[i].block == b.pins[i].block);
    CHECK(same_bits(a.pins[i].anchor, b.pins[i].anchor));
    CHECK(same_bits(a.pins[i].initial, b.pins[i].initial));
    CHECK(same_bits(a.pins[i].current, b.pins[i].current));
  }
  REQUIRE(a.loads.size() == b.loads.size());
  for (std::size_t i = 0; i < a.loads.size(); ++i) {
    CHECK(a.loads[i].block == b.loads[i].block);
    CHECK(same_bits(a.loads[i].initial, b.loads[i].initial));
    CHECK(same_bits(a.loads[i].current, b.loads[i].current));
    CHECK(same_bits(a.loads[i].force, b.loads[i].force));
  }
  REQUIRE(a.monitors.size() == b.monitors.size());
  for (std::size_t i = 0; i < a.monitors.size(); ++i) {
    CHECK(a.monitors[i].name == b.monitors[i].name);
    CHECK(a.monitors[i].block == b.monitors[i].block);
    CHECK(same_bits(a.monitors[i].initial, b.monitors[i].initial));
    CHECK(same_bits(a.monitors[i].current, b.monitors[i].current));
  }
  REQUIRE(a.bolts.size() == b.bolts.size());
  for (std::size_t i = 0; i < a.bolts.size(); ++i) {
    const Bolt& p = a.bolts[i];
    const Bolt& q = b.bolts[i];
    CHECK(p.name == q.name);
    CHECK(same_bits(p.law.stiffness, q.law.stiffness));
    CHECK(same_bits(p.law.yield_force, q.law.yield_force));
    CHECK(same_bits(p.rupture_extension, q.rupture_extension));
    CHECK(same_bits(p.force, q.force));
    CHECK(same_bits(p.plastic_extension, q.plastic_extension));
    CHECK(p.broken == q.broken);
    CHECK(same_bits(p.broken_at, q.broken_at));
  }
  REQUIRE(a.bolt_ends.size() == b.bolt_ends.size());
  for (std::size_t i = 0; i < a.bolt_ends.size(); ++i) {
    CHECK(a.bolt_ends[i].block == b.bolt_ends[i].block);
    CHECK(same_bits(a.bolt_ends[i].initial, b.bolt_ends[i].initial));
    CHECK(same_bits(a.bolt_ends[i].current, b.bolt_ends[i].current));
  }
  CHECK(a.water.has_value() == b.water.has_value());
  CHECK(a.base_motion.has_value() == b.base_motion.has_value());
  SAME(gravity); EQUAL(pseudo_rigid); EQUAL(plane);
  require_same(a.control, b.control);
  SAME(penalty); SAME(w0); SAME(allowed_penetration); SAME(search_distance);
  REQUIRE(a.joint_laws.size() == b.joint_laws.size());
  for (std::size_t i = 0; i < a.joint_laws.size(); ++i) require_same(a.joint_laws[i], b.joint_laws[i]);
  EQUAL(pair_joint); EQUAL(dof_count);
  REQUIRE(a.contacts.size() == b.contacts.size());
  for (std::size_t i = 0; i < a.contacts.size(); ++i) {
    INFO("contact " << i);
    require_same(a.contacts[i], b.contacts[i]);
  }
  SAME(time); EQUAL(step); SAME(step_size.next);
  SAME(energy.load_work); SAME(energy.multiplier_work); SAME(energy.friction_dissipation);
  SAME(energy.plastic_dissipation); SAME(energy.damping_dissipation); SAME(energy.friction_gain);
  SAME(energy.contact_energy); SAME(energy.excavation); SAME(energy.initial_total);
  SAME(energy.remainder); SAME(energy.remainder_max); EQUAL(energy.remainder_max_step);
  SAME(energy.remainder_min); EQUAL(energy.remainder_min_step); SAME(energy.scale);
  CHECK(a.stages.stages.size() == b.stages.stages.size());
  EQUAL(stages.end_times); SAME(stages.gravity);
  require_same(a.stages.control, b.stages.control);
  REQUIRE(a.stages.joint_laws.size() == b.stages.joint_laws.size());
  for (std::size_t i = 0; i < a.stages.joint_laws.size(); ++i) {
    require_same(a.stages.joint_laws[i], b.stages.joint_laws[i]);
  }
  EQUAL(stages.current); EQUAL(stages.start_steps); EQUAL(stages.bonds_formed);
}

// The counts that do not depend on the clock.
void require_same(const RunStats& a, const RunStats& b) {
  EQUAL(steps); EQUAL(cut_steps); EQUAL(cuts_for_displacement); EQUAL(cuts_for_open_close);
  EQUAL(cuts_for_penetration); EQUAL(cuts_for_material); EQUAL(cuts_for_overshoot);
  SAME(smallest_time_step); SAME(largest_time_step); EQUAL(steps_below_schedule);
  EQUAL(iterations); EQUAL(open_close_total); EQUAL(open_close_max); EQUAL(contacts_total);
  EQUAL(contacts_max); EQUAL(contacts_final); EQUAL(candidate_pairs_max);
  SAME(deepest_penetration); SAME(largest_normal_force); EQUAL(augmentations);
  EQUAL(line_searches_shortened); SAME(newton_unconverged_mismatch);
  EQUAL(newton_accepted_unconverged); EQUAL(newton_held_open); EQUAL(bonds_broken);
  EQUAL(broken_bonds.size()); EQUAL(local_secant_settles); EQUAL(diverged); EQUAL(message);
}

#undef SAME
#undef EQUAL

// Runs `world` until step `stop` (0: to its end), counting into `stats`.
void run_until(World& world, RunStats& stats, int stop) {
  const auto go_on = [stop](const World& w, const RunStats&) { return stop == 0 || w.step < stop; };
  run(world, RunHook{{}, {}, go_on}, stats);
}

}  // namespace

TEST_CASE("A checkpoint reads back as the world it was written from, field by field",
          "[checkpoint]") {
  const std::string text = dda::test::checkpoint_scene();
  const Scene scene = parse_scene_text(text, "checkpoint scene");
  World world = make_world(scene);
  RunStats stats;
  run_until(world, stats, 13);  // inside the dynamic stage, with contacts sliding and bonded
  REQUIRE(world.step == 13);
  REQUIRE_FALSE(world.contacts.empty());
  OutputProgress output;
  output.frames = {{0.0, "vtk/step_000000.vtp"}, {0.015, "vtk/step_000003.vtp"}};
  output.history = {1234, 987654321};
  const std::string bytes = encode_checkpoint({text, scene, world, stats, output});
  const Checkpoint back = decode_checkpoint(bytes, "memory");
  CHECK(back.scene_text == text);
  CHECK(back.scene.source == "checkpoint scene");
  require_same(world, back.world);
  require_same(stats, back.stats);
  CHECK(back.output.frames == output.frames);
  CHECK(back.output.history.bytes == 1234);
  CHECK(back.output.history.digest == 987654321);
  // Written again, the world read back gives the same bytes.
  CHECK(encode_checkpoint({text, back.scene, back.world, back.stats, back.output}) == bytes);
}

TEST_CASE("A run stopped at any step and continued from its checkpoint ends as the run in one piece",
          "[checkpoint]") {
  const std::string text = dda::test::checkpoint_scene();
  const Scene scene = parse_scene_text(text, "checkpoint scene");
  World whole = make_world(scene);
  RunStats whole_stats;
  run_until(whole, whole_stats, 0);
  REQUIRE(whole.step == 26);  // 10 static steps, then 16 dynamic ones
  // The scene does what the checkpoint must carry: the soil yielded, the slider slid.
  CHECK(whole.blocks[1].material_state.eps_p > 0.0);
  CHECK(whole.blocks[4].translation.norm() > 1e-3);
  CHECK(whole.stages.current == 1);
  // Split at the first step, in the ramp, at the stage change (step 10 ends the first
  // stage; the second begins with step 11), just after it, and at the last step but one.
  for (const int k : {1, 5, 9, 10, 11, 17, 25}) {
    INFO("split at step " << k);
    World first = make_world(scene);
    RunStats stats;
    run_until(first, stats, k);
    REQUIRE(first.step == k);
    const std::string bytes = encode_checkpoint({text, scene, first, stats, OutputProgress{}});
    Checkpoint resumed = decode_checkpoint(bytes, "memory");
    resumed.stats.interrupted = false;
    run_until(resumed.world, resumed.stats, 0);
    require_same(whole, resumed.world);
    require_same(whole_stats, resumed.stats);
  }
}

TEST_CASE("With the kept factor a run stopped at any step continues from its file bit for bit",
          "[checkpoint]") {
  // The same scene on the default solver path ("linear_solver": "reuse": the factor is kept
  // from step to step, updated by the springs that changed, and CG makes up the rest): the
  // checkpoint stores the kept factor (WorkspaceRecord) and the continued run rebuilds it,
  // so it takes the paths, and reaches the answers, of the run never stopped.
  const std::string text = dda::test::checkpoint_scene("0.08", "reuse");
  const Scene scene = parse_scene_text(text, "checkpoint scene");
  REQUIRE(scene.control.reuse_factor);
  World whole = make_world(scene);
  StepWorkspace whole_ws;
  RunStats whole_stats;
  run(whole, whole_ws, RunHook{}, whole_stats);
  REQUIRE(whole.step == 26);
  REQUIRE(whole_ws.solver.stats().reused > 0);  // the kept factor was used
  for (const int k : {1, 5, 10, 11, 17, 25}) {
    INFO("split at step " << k);
    World first = make_world(scene);
    StepWorkspace first_ws;
    RunStats stats;
    const auto go_on = [k](const World& w, const RunStats&) { return w.step < k; };
    run(first, first_ws, RunHook{{}, {}, go_on}, stats);
    REQUIRE(first.step == k);
    const std::string bytes = encode_checkpoint({text, scene, first, stats, OutputProgress{}, &first_ws});
    Checkpoint resumed = decode_checkpoint(bytes, "memory");
    REQUIRE(resumed.workspace);
    StepWorkspace resumed_ws;
    REQUIRE(restore_workspace(resumed_ws, *resumed.workspace));
    // Written again from the rebuilt workspace: the same bytes.
    CHECK(encode_checkpoint({text, resumed.scene, resumed.world, resumed.stats, resumed.output,
                             &resumed_ws}) == bytes);
    resumed.stats.interrupted = false;
    run(resumed.world, resumed_ws, RunHook{}, resumed.stats);
    require_same(whole, resumed.world);
    require_same(whole_stats, resumed.stats);
    CHECK(resumed_ws.solver.stats().cg_iterations == whole_ws.solver.stats().cg_iterations);
  }
}

TEST_CASE("A file that is not a whole checkpoint of this version is refused naming it",
          "[checkpoint]") {
  const std::string text = dda::test::checkpoint_scene();
  const Scene scene = parse_scene_text(text, "checkpoint scene");
  World world = make_world(scene);
  RunStats stats;
  run_until(world, stats, 3);
  const std::string bytes = encode_checkpoint({text, scene, world, stats, OutputProgress{}});
  const auto refused = [](const std::string& b, const std::string& why) {
    INFO(why);
    try {
      decode_checkpoint(b, "saved.ddack");
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Catch::Contains("saved.ddack: not a checkpoint dda can read"));
      CHECK_THAT(e.what(), Catch::Contains(why));
    }
  };
  refused("", "does not begin as a dda checkpoint does");
  refused("{\"gravity\": [0, -9.81]}", "does not begin as a dda checkpoint does");
  refused(bytes.substr(0, bytes.size() / 2), "cut short");
  refused(bytes.substr(0, bytes.size() - 1), "cut short");
  std::string other_version = bytes;
  other_version[8] = static_cast<char>(kCheckpointVersion + 1);
  refused(other_version, "format version " + std::to_string(kCheckpointVersion + 1));
  std::string damaged = bytes;
  damaged[bytes.size() / 2] ^= 0x10;
  refused(damaged, "checksum");
  std::string swapped = bytes;
  std::swap(swapped[12], swapped[15]);
  refused(swapped, "byte order");
}
