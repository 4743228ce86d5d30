#include "report.hpp"

#include <sstream>

#include "conclusion.hpp"
#include "csv.hpp"

namespace dda::paper {
namespace {

// The first run of a treatment that did not complete, to say why (or nullptr).
template <class Runs>
const RunResult* first_failure(const Runs& runs, std::string_view treatment) {
  for (const auto& r : runs) {
    if (r.treatment == treatment && r.result.status != RunStatus::Completed) return &r.result;
  }
  return nullptr;
}

std::string availability(const Options& opt, const AllResults& r) {
  std::ostringstream md;
  md << "## Treatments\n\n"
     << "Selected by `control.rotation_update`. A treatment the library names but does not "
        "implement yet is listed as not available; one whose step fails is listed with the "
        "step.\n\n| treatment | paper's name | status in this run |\n|---|---|---|\n";
  for (const Treatment& t : treatments_for(opt.smoke)) {
    std::string status = "available, every run completed";
    const RunResult* bad = first_failure(r.falling, t.name);
    if (!bad) bad = first_failure(r.swinging, t.name);
    if (!bad) bad = first_failure(r.speed.spin, t.name);
    if (!bad) bad = first_failure(r.speed.pendulum, t.name);
    if (bad) {
      status = "available; at least one run diverged (see the tables)";
    }
    md << "| " << t.name << " | " << (t.paper.empty() ? "-" : std::string(t.paper)) << " | "
       << status << " |\n";
  }
  if (opt.smoke) {
    md << "\nSmoke run: only the treatments above; the full run covers all of:";
    for (const Treatment& t : all_treatments()) md << ' ' << t.name;
    md << ".\n";
  }
  md << '\n';
  return md.str();
}

}  // namespace

std::string full_report(const Options& opt, const AllResults& r) {
  std::ostringstream md;
  md << "# Paper reproduction: Jiang and Zheng (2015), Section 5\n\n"
     << "W. Jiang, H. Zheng, \"An efficient remedy for the false volume expansion of DDA when "
        "simulating large rotation\", Computers and Geotechnics (2015). Written by "
        "`dda_verify_paper --out DIR"
     << (opt.smoke ? " --smoke" : "")
     << "` (verification/paper/, one command: `verification/paper/run.sh DIR`), which also "
        "writes the CSVs beside this file; `verification/paper/plot_paper.py DIR` draws the "
        "PNGs from them. " << (opt.smoke ? "**This is a smoke run (CI): few steps and three "
                                            "treatments; the numbers are not the paper's "
                                            "cases.** " : "")
     << "Wall time of the program: " << sig(r.wall_s, 3) << " s.\n\n"
     << "Files: falling_scene.csv, falling_area.csv (area error against step, every run), "
        "falling_path.csv (the rock's outline every 20 steps), falling_summary.csv; "
        "swinging_diagonals.csv, swinging_strains.csv, swinging_energy.csv, "
        "swinging_summary.csv; speed_spin.csv, speed_pendulum.csv, speed_incline.csv, "
        "speed_plastic.csv; rotation_spin.csv, rotation_swing.csv, rotation_swing_summary.csv, "
        "rotation_table3.csv, rotation_gain.csv, rotation_damping.csv, rotation_pendulum.csv; PNGs: falling_scene.png, "
        "falling_area_error.png, swinging_energy.png, speed_error.png, speed_incline.png, "
        "speed_plastic.png, rotation_stress.png.\n\n";
  md << availability(opt, r);
  md << conclusion_report(opt, r);
  md << falling_report(opt, r.falling);
  md << swinging_report(opt, r.swinging);
  md << speed_report(opt, r.speed);
  md << rotation_report(opt, r.rotation);
  return md.str();
}

}  // namespace dda::paper
