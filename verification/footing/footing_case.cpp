#include "footing_case.hpp"

#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "io/scene_reader.hpp"
#include "solver/moving_anchors.hpp"
#include "solver/run.hpp"
#include "solver/world.hpp"

namespace dda::footing {

namespace {

using Json = nlohmann::ordered_json;

Json point(double x, double y) { return Json::array({x, y}); }

Json rectangle(double x0, double y0, double x1, double y1) {
  return Json::array({point(x0, y0), point(x1, y0), point(x1, y1), point(x0, y1)});
}

int cells(double extent, double h, const char* what) {
  const double n = extent / h;
  const long rounded = std::lround(n);
  if (rounded < 1 || std::abs(n - static_cast<double>(rounded)) > 1e-9 * n) {
    throw std::invalid_argument(std::string("footing case: ") + what +
                                " is not a whole number of cells");
  }
  return static_cast<int>(rounded);
}

// CPU time of the calling thread (s): the cost of a run on a machine others share, where
// the wall time also counts their work (CHOLMOD runs single-threaded here).
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

constexpr double kFootingThickness = 0.25;  // m
constexpr double kWall = 0.5;               // thickness of the fixed walls (m)

}  // namespace

const char* mesh_name(Mesh m) {
  switch (m) {
    case Mesh::Crossed: return "crossed";
    case Mesh::Diagonal: return "diagonal";
    case Mesh::Uniform: return "uniform";
  }
  return "?";
}

std::string FootingCase::label() const {
  char buf[96];
  if (!rotation_update.empty()) {
    std::snprintf(buf, sizeof buf, "%s_h%g_n%d_%s", mesh_name(mesh), cell, steps, rotation_update.c_str());
  } else if (penalty_factor != 50.0) {
    std::snprintf(buf, sizeof buf, "%s_h%g_n%d_p%g", mesh_name(mesh), cell, steps, penalty_factor);
  } else if (friction_angle == 0.0) {
    std::snprintf(buf, sizeof buf, "%s_h%g_n%d", mesh_name(mesh), cell, steps);
  } else {
    std::snprintf(buf, sizeof buf, "%s_h%g_n%d_phi%g", mesh_name(mesh), cell, steps, friction_angle);
  }
  return buf;
}

Scene footing_scene(const FootingCase& c) {
  const int nx = cells(c.length, c.cell, "the layer's length");
  const int ny = cells(c.depth, c.cell, "the layer's depth");
  cells(c.half_width, c.cell, "the footing's half width");
  const double h = c.cell;
  const double tf = kFootingThickness;

  Json blocks = Json::array();
  auto add = [&](Json vertices, const char* material, bool fixed) {
    Json b = {{"vertices", std::move(vertices)}, {"material", material}};
    if (fixed) b["fixed"] = true;
    blocks.push_back(std::move(b));
  };
  // 0: the symmetry plane x = 0 (smooth, up past the footing); 1: the base (rough,
  // bonded); 2: the far wall (rough, bonded).
  add(rectangle(-kWall, -c.depth, 0.0, tf + kWall), "wall", true);
  add(rectangle(-kWall, -c.depth - kWall, c.length + kWall, -c.depth), "wall", true);
  add(rectangle(c.length, -c.depth, c.length + kWall, 0.0), "wall", true);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double x0 = i * h, y0 = -c.depth + j * h, x1 = x0 + h, y1 = y0 + h;
      if (c.mesh == Mesh::Crossed) {
        const double xm = x0 + 0.5 * h, ym = y0 + 0.5 * h;
        add(Json::array({point(x0, y0), point(x1, y0), point(xm, ym)}), "soil", false);
        add(Json::array({point(x1, y0), point(x1, y1), point(xm, ym)}), "soil", false);
        add(Json::array({point(x1, y1), point(x0, y1), point(xm, ym)}), "soil", false);
        add(Json::array({point(x0, y1), point(x0, y0), point(xm, ym)}), "soil", false);
      } else {
        // One diagonal a cell: alternating cell by cell (a chequer), or all the same way.
        if (c.mesh == Mesh::Uniform || (i + j) % 2 == 0) {
          add(Json::array({point(x0, y0), point(x1, y0), point(x1, y1)}), "soil", false);
          add(Json::array({point(x0, y0), point(x1, y1), point(x0, y1)}), "soil", false);
        } else {
          add(Json::array({point(x0, y0), point(x1, y0), point(x0, y1)}), "soil", false);
          add(Json::array({point(x1, y0), point(x1, y1), point(x0, y1)}), "soil", false);
        }
      }
    }
  }
  const int footing = static_cast<int>(blocks.size());
  add(rectangle(0.0, 0.0, c.half_width, tf), "footing", false);

  // Smooth joints: the layer on the symmetry plane, the footing on the layer and on the
  // symmetry plane. Every other pair (block to block, layer to base and far wall) is bonded
  // far above the soil's strength.
  Json joints = Json::array();
  for (int k = 3; k < footing; ++k) {
    joints.push_back({{"blocks", {0, k}}, {"material", "smooth"}});
    joints.push_back({{"blocks", {k, footing}}, {"material", "smooth"}});
  }
  joints.push_back({{"blocks", {0, footing}}, {"material", "smooth"}});

  const double strong = 1e3 * c.cohesion;
  Json scene = {
      {"description",
       "Smooth rigid strip footing (half model) pressed into a weightless Tresca layer of "
       "constant-strain triangular blocks bonded far above the soil's strength "
       "(verification/footing). The pins' anchors are moved by dda_verify_footing; run "
       "as it stands, nothing is loaded."},
      {"gravity", point(0.0, 0.0)},
      {"plane", "strain"},
      {"control",
       {{"time_step", c.time_step},
        {"steps", c.steps},
        {"max_displacement_ratio", c.max_displacement_ratio},
        {"dynamic_coefficient", 0.0},
        {"penalty", c.penalty_factor * c.young},
        {"output_every", c.steps}}},
      {"materials",
       {{"footing",
         {{"model", "elastic"}, {"density", c.density}, {"young", c.young},
          {"poisson", c.poisson}, {"rigid", true}}},
        {"soil",
         {{"model", "mohr_coulomb"}, {"density", c.density}, {"young", c.young},
          {"poisson", c.poisson}, {"cohesion", c.cohesion},
          {"friction_angle", c.friction_angle}, {"dilation_angle", c.friction_angle}}},
        {"wall",
         {{"model", "elastic"}, {"density", c.density}, {"young", c.young},
          {"poisson", c.poisson}}}}},
      {"joint_materials",
       {{"default",
         {{"friction_angle", 0.0}, {"cohesion", strong}, {"tensile_strength", strong},
          {"law", "coulomb_slip"}}},
        {"smooth", {{"friction_angle", 0.0}, {"cohesion", 0.0}, {"tensile_strength", 0.0}}}}},
      {"blocks", std::move(blocks)},
      {"joints", std::move(joints)},
      {"pins", Json::array({{{"point", point(0.25 * c.half_width, 0.5 * tf)}},
                            {{"point", point(0.75 * c.half_width, 0.5 * tf)}}})},
  };
  if (!c.rotation_update.empty()) scene["control"]["rotation_update"] = c.rotation_update;
  return parse_scene_text(scene.dump(), "footing " + c.label());
}

double prandtl_pressure(double cohesion, double friction_angle_deg) {
  if (friction_angle_deg == 0.0) return (2.0 + M_PI) * cohesion;
  const double phi = friction_angle_deg * M_PI / 180.0;
  const double t = std::tan(M_PI / 4.0 + phi / 2.0);
  const double nq = std::exp(M_PI * std::tan(phi)) * t * t;
  return cohesion * (nq - 1.0) / std::tan(phi);
}

FootingResult run_footing(const FootingCase& c) {
  const Scene scene = footing_scene(c);
  World world = make_world(scene);
  const int footing = static_cast<int>(world.blocks.size()) - 1;
  FootingResult r;
  r.blocks = footing - 3;
  const double per_step = c.settlement / c.steps;
  RunStats stats;
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_seconds();
  // Pairs of layer blocks that share an edge (two common corners): their contacts are the
  // bonds that hold the mesh together; the others meet at a corner only.
  std::unordered_set<std::uint64_t> edge_pairs;
  for (int a = 3; a < footing; ++a) {
    for (int e = a + 1; e < footing; ++e) {
      int common = 0;
      for (const Vec2& x : world.blocks[static_cast<std::size_t>(a)].initial_vertices) {
        for (const Vec2& y : world.blocks[static_cast<std::size_t>(e)].initial_vertices) {
          if ((x - y).norm() <= 1e-9 * c.cell) ++common;
        }
      }
      if (common >= 2) edge_pairs.insert(pair_key(a, e));
    }
  }
  long solves_before = 0;
  int reasons_before[5] = {0, 0, 0, 0, 0};
  double time_before = 0.0;
  int cuts_before = 0;
  auto record = [&](int step) {
    double force = 0.0;  // upward force of the layer on the footing = the pins' pull down
    for (const Pin& p : world.pins) force += world.penalty * (p.current.y() - p.anchor.y());
    int yielding = 0;
    for (int k = 3; k < footing; ++k) {
      if (world.blocks[static_cast<std::size_t>(k)].branch != Branch::Elastic) ++yielding;
    }
    const double settlement = -world.blocks[static_cast<std::size_t>(footing)].translation.y();
    CurvePoint p;
    p.step = step;
    p.settlement = settlement;
    p.pressure = force / c.half_width;
    p.yielding = yielding;
    for (const Contact& ct : world.contacts) {
      const int a = ct.key.vertex_block, e = ct.key.edge_block;
      if (a < 3 || e < 3 || a >= footing || e >= footing) continue;
      if (!edge_pairs.contains(pair_key(a, e))) {
        if (ct.state.mode != ContactMode::Open) ++p.corner_closed;
        continue;
      }
      if (ct.state.mode == ContactMode::Lock) ++p.edge_locked;
      else if (ct.state.mode == ContactMode::Slide) ++p.edge_sliding;
      else ++p.edge_open;
      if (!ct.state.bonded) ++p.edge_unbonded;
    }
    p.solves = stats.iterations - solves_before;
    p.cuts = stats.cut_steps - cuts_before;
    const int now[5] = {stats.cuts_for_displacement, stats.cuts_for_open_close, stats.cuts_for_penetration,
                        stats.cuts_for_material, stats.cuts_for_overshoot};
    for (int i = 0; i < 5; ++i) {
      if (now[i] > reasons_before[i]) p.cut_reasons += "dopmv"[i] + std::to_string(now[i] - reasons_before[i]);
      reasons_before[i] = now[i];
    }
    p.energy_remainder = world.energy.remainder;
    p.dt = world.time - time_before;
    time_before = world.time;
    solves_before = stats.iterations;
    cuts_before = stats.cut_steps;
    r.curve.push_back(p);
  };
  // The driver presses the footing in through its pins (solver/moving_anchors.hpp), a fixed
  // distance each step, and records the curve after every step.
  const std::function<void(World&)> press = moving_anchors(Vec2(0.0, -per_step));
  int attempting = 0;  // the step being taken, for the message of one that fails
  RunHook hook;
  hook.at_start = [&](const World&, const RunStats&) {
    record(0);
    return true;
  };
  hook.before_step = [&](World& w) {
    attempting = w.step + 1;
    press(w);
  };
  hook.after_step = [&](const World& w, const RunStats&) {
    record(w.step);
    return true;
  };
  run(world, hook, stats);
  if (stats.diverged) {
    r.ok = false;
    r.message = "step " + std::to_string(attempting) + ": " + stats.message;
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cpu_s = thread_cpu_seconds() - cpu0;
  r.final_pressure = r.curve.back().pressure;
  r.cut_steps = stats.cut_steps;
  r.solves = stats.iterations;
  r.open_close_max = stats.open_close_max;
  r.energy_remainder_max = world.energy.remainder_max;
  r.energy_scale = world.energy.scale;
  for (int k = 3; k < footing; ++k) {
    const Block& b = world.blocks[static_cast<std::size_t>(k)];
    r.zone.polygons.push_back(b.vertices);
    r.zone.eps_p.push_back(b.material_state.eps_p);
  }
  return r;
}

}  // namespace dda::footing
