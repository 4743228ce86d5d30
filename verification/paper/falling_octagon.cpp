#include "falling_octagon.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "csv.hpp"
#include "paper_scenes.hpp"

namespace dda::paper {
namespace {

// The rock's outline is kept every this many steps, for the drawing of its path.
constexpr int kPathEvery = 20;
// Smoke runs: this many steps per setting (enough for the rock to strike the first steps).
constexpr int kSmokeSteps = 100;

// Paper Table 1, areas (m^2) for the settings in table1_settings() order.
const std::map<std::string, std::vector<double>>& paper_areas() {
  static const std::map<std::string, std::vector<double>> kAreas = {
      {"original", {0.834560, 1.264527, 1.132795}},
      {"post_adjustment", {0.707120, 0.707114, 0.707113}},
      {"sin_variable", {0.708365, 0.731127, 0.742573}},
      {"local_frame", {0.707119, 0.707116, 0.707119}},
  };
  return kAreas;
}
// The paper's initial area (Table 1), for its relative errors.
constexpr double kPaperInitialArea = 0.707107;

const Block& rock(const World& w) { return w.blocks.back(); }

FallingRun run_one(const Treatment& t, const FallingSetting& setting, int steps) {
  FallingRun run;
  run.treatment = std::string(t.name);
  run.setting = setting.name;
  World world = make_world(falling_octagon_scene(setting, steps, t.value));
  run.initial_area = rock(world).initial_area;
  double last_rotation = 0.0;
  run.result = run_world(world, [&](const World& w) {
    const Block& b = rock(w);
    run.samples.push_back({w.step, w.time, b.moments.area, b.rotation, b.velocity[kR0],
                           b.moments.centroid});
    run.turned += std::abs(b.rotation - last_rotation);
    last_rotation = b.rotation;
    if (w.step % kPathEvery == 0) run.path.emplace_back(w.step, b.vertices);
  });
  if (run.path.empty() || run.path.back().first != world.step) {
    run.path.emplace_back(world.step, rock(world).vertices);
  }
  return run;
}

double rel_error(double area, double a0) { return std::abs(area - a0) / a0; }

}  // namespace

std::vector<FallingRun> run_falling(const Options& opt) {
  std::vector<FallingRun> runs;
  for (const Treatment& t : treatments_for(opt.smoke)) {
    for (const FallingSetting& s : table1_settings()) {
      runs.push_back(run_one(t, s, opt.smoke ? kSmokeSteps : s.steps));
    }
  }
  return runs;
}

void write_falling_csv(const Options& opt, const std::vector<FallingRun>& runs) {
  {
    WholeFile out = open_csv(opt.out, "falling_scene.csv", "block,role,vertex,x,y");
    const Staircase stairs = table1_staircase();
    const std::vector<Polygon> blocks = staircase_blocks(stairs);
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      for (std::size_t k = 0; k < blocks[i].size(); ++k) {
        out << i << ",fixed," << k << ',' << full(blocks[i][k].x()) << ','
            << full(blocks[i][k].y()) << '\n';
      }
    }
    const Launch l = table1_launch(stairs);
    const Polygon octagon = regular_octagon(l.centre, 0.5, l.first_angle);
    for (std::size_t k = 0; k < octagon.size(); ++k) {
      out << blocks.size() << ",rock," << k << ',' << full(octagon[k].x()) << ','
          << full(octagon[k].y()) << '\n';
    }
    out.finish();
  }
  WholeFile area =
      open_csv(opt.out, "falling_area.csv",
               "treatment,setting,step,time,area,area_rel_error,rotation,omega,xc,yc");
  WholeFile path = open_csv(opt.out, "falling_path.csv", "treatment,setting,step,vertex,x,y");
  for (const FallingRun& r : runs) {
    for (const FallingSample& s : r.samples) {
      area << r.treatment << ',' << r.setting << ',' << s.step << ',' << full(s.time) << ','
           << full(s.area) << ',' << full(rel_error(s.area, r.initial_area)) << ','
           << full(s.rotation) << ',' << full(s.omega) << ',' << full(s.centroid.x()) << ','
           << full(s.centroid.y()) << '\n';
    }
    for (const auto& [step, poly] : r.path) {
      for (std::size_t k = 0; k < poly.size(); ++k) {
        path << r.treatment << ',' << r.setting << ',' << step << ',' << k << ','
             << full(poly[k].x()) << ',' << full(poly[k].y()) << '\n';
      }
    }
  }
  area.finish();
  path.finish();
  WholeFile sum = open_csv(opt.out, "falling_summary.csv",
                           "treatment,setting,status,steps,time,initial_area,final_area,"
                           "area_rel_error,paper_area,paper_rel_error,rotation,turned,"
                           "cut_steps");
  const std::vector<FallingSetting> settings = table1_settings();
  for (const FallingRun& r : runs) {
    const FallingSample& last = r.samples.back();
    double paper = NAN;
    const auto it = paper_areas().find(r.treatment);
    for (std::size_t i = 0; i < settings.size(); ++i) {
      if (it != paper_areas().end() && r.setting == settings[i].name) paper = it->second[i];
    }
    sum << r.treatment << ',' << r.setting << ',' << status_word(r.result.status) << ','
        << r.result.steps_done << ',' << full(last.time) << ',' << full(r.initial_area) << ','
        << full(last.area) << ',' << full(rel_error(last.area, r.initial_area)) << ','
        << full(paper) << ',' << full(rel_error(paper, kPaperInitialArea)) << ','
        << full(last.rotation) << ',' << full(r.turned) << ',' << r.result.stats.cut_steps << '\n';
  }
  sum.finish();
}

std::string falling_report(const Options& opt, const std::vector<FallingRun>& runs) {
  const Staircase st = table1_staircase();
  const Launch l = table1_launch(st);
  std::ostringstream md;
  md << "## Table 1: the falling octagon\n\n"
     << "The paper does not give its slope (docs/paper-errata.md, item 4); this one is a staircase of "
        "fixed blocks, so that the rock strikes tread edges and turns (on a plane frictionless "
        "slope it would only slide): "
     << st.steps << " steps, each " << fixed(st.tread, 2) << " m deep and " << fixed(st.riser, 2)
     << " m high (overall slope " << fixed(std::atan2(st.riser, st.tread) * 180.0 / M_PI, 1)
     << " degrees), the top tread at y = " << fixed(st.steps * st.riser, 2)
     << " m from x = 0 to " << fixed(st.tread, 2) << " m; then a flat run-out at y = 0 from x = "
     << fixed(st.steps * st.tread, 2) << " to " << fixed(st.steps * st.tread + st.runout, 2)
     << " m closed by a wall " << fixed(st.wall_height, 2) << " m high and "
     << fixed(st.wall_width, 2) << " m thick; every fixed block stands on y = "
     << fixed(st.base_y, 2) << " m. The rock: a regular octagon of circumscribed diameter 1 m "
        "(area 0.707107 m^2), a vertex pointing straight down, centre at ("
     << fixed(l.centre.x(), 2) << ", " << fixed(l.centre.y(), 2)
     << ") m (its lowest point 0.5 m above the top tread), thrown horizontally at "
     << fixed(l.velocity.x(), 2)
     << " m/s without spin. Unit weight 28 kN/m^3, E = 2 GPa, nu = 0.25, plane strain, "
        "friction angle 0, cohesion 0, penalty and allowed penetration auto. Drawing: "
        "falling_scene.png (blocks, and the rock every 20 steps for each setting, "
        "`original`); area error against step: falling_area_error.png.\n\n"
     << "RE = |A - A0| / A0. \"Rotation\" is the rock's net rotation at the end, \"turned\" "
        "the sum of the absolute rotation of every step (what inflates the `original` rock); "
        "\"end x, y\" the rock's final centroid (the run-out starts at x = "
     << fixed(st.steps * st.tread, 2) << " m; resting on it, y = 0.46 to 0.5 m). "
        "Time is the simulated time reached (steps cut by the displacement-ratio control are "
        "shorter than scheduled). Each setting's ratio is the paper's g2, a share of w0 (half "
        "the scene's larger extent, 6.25 m); this program measures the ratio against each "
        "block, so the rock runs with g2 x w0 / 0.5 m, the same metres a step.";
  if (opt.smoke) md << " **Smoke run: only the first steps of each setting.**";
  md << "\n\n";
  for (const FallingSetting& s : table1_settings()) {
    md << "### " << s.label << "\n\n"
       << "| treatment | area (m^2) | RE (%) | paper area | paper RE (%) | rotation (rad) | "
          "turned (rad) | time (s) | end x, y (m) | cut steps | run |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---|\n";
    for (const FallingRun& r : runs) {
      if (r.setting != s.name) continue;
      std::string paper_area = "-", paper_re = "-";
      const auto it = paper_areas().find(r.treatment);
      if (it != paper_areas().end()) {
        const std::vector<FallingSetting> all = table1_settings();
        for (std::size_t i = 0; i < all.size(); ++i) {
          if (all[i].name == std::string(s.name)) {
            paper_area = fixed(it->second[i], 6);
            paper_re = fixed(100.0 * rel_error(it->second[i], kPaperInitialArea), 3);
          }
        }
      }
      const FallingSample& last = r.samples.back();
      md << "| " << r.treatment << " | " << fixed(last.area, 6) << " | "
         << sig(100.0 * rel_error(last.area, r.initial_area), 4) << " | " << paper_area << " | "
         << paper_re << " | " << fixed(last.rotation, 2) << " | " << fixed(r.turned, 2) << " | "
         << fixed(last.time, 3) << " | " << fixed(last.centroid.x(), 2) << ", "
         << fixed(last.centroid.y(), 2) << " | " << r.result.stats.cut_steps << " | "
         << describe(r.result) << " |\n";
    }
    md << '\n';
  }
  return md.str();
}

}  // namespace dda::paper
