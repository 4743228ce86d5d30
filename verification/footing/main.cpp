// dda_verify_footing --out DIR [--smoke] [--cells H,H,...] [--steps N,N,...]
//                    [--mesh crossed|diagonal|uniform|both|all] [--jobs N]
// A smooth rigid strip footing pressed into a weightless Tresca layer of plastic blocks
// against Prandtl's (2 + pi) c (verification/footing/README.md). Writes
// curves.csv (the load-settlement curve of every run), runs.csv (one row a run: the limit
// pressure, its error against Prandtl, the cost), zone_<label>.csv (each block's outline and
// plastic strain at the end) and report.md into DIR, and prints the report. Exit codes: 0 done (a run that stops early is a
// result in the report); 1 output could not be written; 2 bad arguments.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../common/format.hpp"
#include "footing_case.hpp"

namespace {

using namespace dda::footing;
namespace fmt = dda::verification;

constexpr const char* kUsage =
    "usage: dda_verify_footing --out DIR [--smoke] [--cells H,...] [--steps N,...] [--mesh crossed|diagonal|uniform|both|all] [--phi DEG] [--penalty F] [--dt S] [--rotation R] [--jobs N]\n"
    "  --out DIR     write curves.csv, runs.csv, zone_*.csv and report.md into DIR\n"
    "  --smoke       the coarsest crossed mesh (h = 0.5 m) at 150 steps only\n"
    "  --cells LIST  cell sides h (m), default 0.5,0.25,0.125,0.0625\n"
    "  --steps LIST  steps over the 6 cm push, default 150,300 (300 not on the finest cell)\n"
    "  --mesh M      crossed (default: both diagonals a cell), diagonal (one, alternating),\n"
    "                uniform (one, all the same way), both (crossed and diagonal) or all\n"
    "  --phi DEG     the soil's friction angle (= dilation angle: associated), default 0 (Tresca)\n"
    "  --penalty F   contact and pin penalty F x E (default 50, Shi's auto)\n"
    "  --dt S        the static steps' time step (s), default 0.01; it enters only their\n"
    "                relaxation term 2 M / dt^2 (verification/work-precision/README.md)\n"
    "  --rotation R  control.rotation_update (default the scene's, finite_rotation_polar)\n"
    "  --jobs N      runs at once (default 1)\n";

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(std::stod(item));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path out;
  bool smoke = false;
  std::vector<double> cells_list{0.5, 0.25, 0.125, 0.0625};
  std::vector<double> steps_list{150, 300};
  bool custom_steps = false;
  std::vector<Mesh> meshes{Mesh::Crossed};
  int jobs = 1;
  double friction = 0.0;
  double penalty = 50.0;
  double time_step = FootingCase{}.time_step;
  std::string rotation;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--smoke") {
        smoke = true;
      } else if (arg == "--out" && i + 1 < argc) {
        out = argv[++i];
      } else if (arg == "--cells" && i + 1 < argc) {
        cells_list = numbers(argv[++i]);
      } else if (arg == "--steps" && i + 1 < argc) {
        steps_list = numbers(argv[++i]);
        custom_steps = true;
      } else if (arg == "--mesh" && i + 1 < argc) {
        const std::string m = argv[++i];
        if (m == "crossed") meshes = {Mesh::Crossed};
        else if (m == "diagonal") meshes = {Mesh::Diagonal};
        else if (m == "uniform") meshes = {Mesh::Uniform};
        else if (m == "both") meshes = {Mesh::Crossed, Mesh::Diagonal};
        else if (m == "all") meshes = {Mesh::Crossed, Mesh::Diagonal, Mesh::Uniform};
        else throw std::invalid_argument("--mesh: " + m);
      } else if (arg == "--penalty" && i + 1 < argc) {
        penalty = std::stod(argv[++i]);
      } else if (arg == "--dt" && i + 1 < argc) {
        time_step = std::stod(argv[++i]);
        if (!(time_step > 0.0)) throw std::invalid_argument("--dt must be positive");
      } else if (arg == "--phi" && i + 1 < argc) {
        friction = std::stod(argv[++i]);
      } else if (arg == "--rotation" && i + 1 < argc) {
        rotation = argv[++i];
      } else if (arg == "--jobs" && i + 1 < argc) {
        jobs = std::max(1, std::atoi(argv[++i]));
      } else if (arg == "--help" || arg == "-h") {
        std::cout << kUsage;
        return 0;
      } else {
        std::cerr << "dda_verify_footing: unexpected argument \"" << arg << "\"\n" << kUsage;
        return 2;
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "dda_verify_footing: bad argument (" << e.what() << ")\n" << kUsage;
    return 2;
  }
  if (out.empty()) {
    std::cerr << "dda_verify_footing: --out DIR is required\n" << kUsage;
    return 2;
  }
  std::vector<FootingCase> cases;
  if (smoke) {
    FootingCase c;
    c.time_step = time_step;
    cases.push_back(c);
  } else {
    const double finest = *std::min_element(cells_list.begin(), cells_list.end());
    for (Mesh m : meshes) {
      for (double h : cells_list) {
        for (double n : steps_list) {
          // The slower load rate is left out on the finest cell unless asked for.
          if (!custom_steps && n != steps_list.front() && h == finest && cells_list.size() > 1) continue;
          FootingCase c;
          c.mesh = m;
          c.cell = h;
          c.steps = static_cast<int>(n);
          c.friction_angle = friction;
          c.penalty_factor = penalty;
          c.time_step = time_step;
          c.rotation_update = rotation;
          cases.push_back(c);
        }
      }
    }
  }
  std::filesystem::create_directories(out);
  const double qu = prandtl_pressure(FootingCase{}.cohesion, friction);
  // curves.csv and runs.csv hold the runs finished so far: both are written again whole
  // (verification/common/whole_file.hpp) as soon as each run ends, so that a study stopped
  // part way keeps the runs it finished and neither file is ever under its name with a part of
  // a row. They are small (a row a step: 1,500 rows for the default study). Written at once
  // with their headers, so that an unwritable directory is known before the runs.
  std::ostringstream curves, runs;
  curves << "label,mesh,cell,steps,step,settlement,pressure,q_over_c,yielding,edge_locked,"
            "edge_sliding,edge_open,edge_unbonded,corner_closed,solves,cuts,cut_reasons,dt,energy_remainder\n";
  runs << "label,mesh,cell,steps,blocks,ok,final_pressure,q_over_c,prandtl_q_over_c,"
          "relative_error,wall_s,cpu_s,solves,cut_steps,open_close_max,"
          "energy_remainder_max,energy_scale,message\n";
  auto write_tables = [&]() {
    fmt::write_whole_file(out / "curves.csv", curves.str());
    fmt::write_whole_file(out / "runs.csv", runs.str());
  };
  try {
    write_tables();
  } catch (const std::exception& e) {
    std::cerr << "dda_verify_footing: " << e.what() << '\n';
    return 1;
  }
  auto write_run = [&](const FootingCase& c, const FootingResult& r) {
    for (const CurvePoint& p : r.curve) {
      curves << c.label() << ',' << mesh_name(c.mesh) << ',' << fmt::full(c.cell) << ',' << c.steps << ','
             << p.step << ',' << fmt::full(p.settlement) << ',' << fmt::full(p.pressure) << ','
             << fmt::full(p.pressure / c.cohesion) << ',' << p.yielding << ',' << p.edge_locked << ','
             << p.edge_sliding << ',' << p.edge_open << ',' << p.edge_unbonded << ',' << p.corner_closed
             << ',' << p.solves << ',' << p.cuts << ',' << p.cut_reasons << ',' << fmt::full(p.dt) << ','
             << fmt::full(p.energy_remainder) << '\n';
    }
    std::string message = r.message;
    std::replace(message.begin(), message.end(), '"', '\'');
    std::replace(message.begin(), message.end(), '\n', ' ');
    runs << c.label() << ',' << mesh_name(c.mesh) << ',' << fmt::full(c.cell) << ',' << c.steps << ','
         << r.blocks << ',' << (r.ok ? 1 : 0) << ',' << fmt::full(r.final_pressure) << ','
         << fmt::full(r.final_pressure / c.cohesion) << ',' << fmt::full(qu / c.cohesion) << ','
         << fmt::full(r.final_pressure / qu - 1.0) << ',' << fmt::full(r.wall_s) << ',' << fmt::full(r.cpu_s)
         << ',' << r.solves << ',' << r.cut_steps << ',' << r.open_close_max << ','
         << fmt::full(r.energy_remainder_max) << ',' << fmt::full(r.energy_scale) << ",\"" << message
         << "\"\n";
    write_tables();
    fmt::WholeFile zone = fmt::open_csv(out, "zone_" + c.label() + ".csv", "block,vertex,x,y,eps_p");
    for (std::size_t b = 0; b < r.zone.polygons.size(); ++b) {
      for (std::size_t v = 0; v < r.zone.polygons[b].size(); ++v) {
        zone << b << ',' << v << ',' << fmt::full(r.zone.polygons[b][v].x()) << ','
             << fmt::full(r.zone.polygons[b][v].y()) << ',' << fmt::full(r.zone.eps_p[b]) << '\n';
      }
    }
    zone.finish();
  };
  std::vector<FootingResult> results(cases.size());
  std::mutex lock_out;
  std::size_t next = 0;
  bool write_failed = false;
  auto worker = [&]() {
    for (;;) {
      std::size_t k;
      {
        std::lock_guard<std::mutex> lock(lock_out);
        if (next >= cases.size()) return;
        k = next++;
      }
      results[k] = run_footing(cases[k]);
      std::lock_guard<std::mutex> lock(lock_out);
      const FootingResult& r = results[k];
      std::cerr << cases[k].label() << ": " << r.blocks << " blocks, q/c "
                << fmt::fixed(r.final_pressure / cases[k].cohesion, 4) << ", "
                << fmt::fixed(r.wall_s, 1) << " s wall, " << fmt::fixed(r.cpu_s, 1) << " s CPU"
                << (r.ok ? "" : ", STOPPED: " + r.message) << '\n';
      try {
        write_run(cases[k], r);
      } catch (const std::exception& e) {
        std::cerr << "dda_verify_footing: " << e.what() << '\n';
        write_failed = true;
      }
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < std::min<int>(jobs, static_cast<int>(cases.size())); ++j) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  if (write_failed) return 1;

  std::ostringstream md;
  md << "| mesh | h (m) | blocks | steps | q/c at s/B = 3 % | error vs Prandtl | wall (s) | CPU (s) | solves | cut steps |\n"
     << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const FootingCase& c = cases[k];
    const FootingResult& r = results[k];
    const double err = r.final_pressure / qu - 1.0;
    md << "| " << mesh_name(c.mesh) << " | " << fmt::significant(c.cell, 4) << " | " << r.blocks
       << " | " << c.steps << " | " << fmt::fixed(r.final_pressure / c.cohesion, 3) << " | "
       << (err >= 0 ? "+" : "") << fmt::fixed(100.0 * err, 1) << " % | " << fmt::fixed(r.wall_s, 1)
       << " | " << fmt::fixed(r.cpu_s, 1) << " | " << r.solves << " | " << r.cut_steps
       << (r.ok ? "" : " (stopped: " + r.message + ")") << " |\n";
  }
  fmt::WholeFile report(out / "report.md");
  report << "# Strip footing on a Tresca layer of blocks against Prandtl\n\n"
         << "Prandtl: q_u / c = " << (friction == 0.0 ? "2 + pi = " : "N_c = ") << fmt::fixed(qu / FootingCase{}.cohesion, 4)
         << " (phi = " << friction << " degrees)"
         << "; footing B = 2 m (half model b = 1 m), E / c = 1000, nu = 0.3, pushed 6 cm (s/B = 3 %).\n\n"
         << md.str();
  if (!report) {
    std::cerr << "dda_verify_footing: cannot write " << (out / "report.md").string() << '\n';
    return 1;
  }
  try {
    report.finish();
  } catch (const std::exception& e) {
    std::cerr << "dda_verify_footing: " << e.what() << '\n';
    return 1;
  }
  std::cout << md.str();
  return 0;
}
