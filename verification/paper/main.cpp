// dda_verify_paper --out DIR [--smoke] [--closed-form-only]: reproduces the examples of Jiang and Zheng (2015),
// Section 5, for every rotation treatment; writes CSVs and report.md into DIR and prints the
// report. Exit codes: 0 done (a treatment that diverges is a result, not a failure); 1 the
// output could not be written; 2 bad arguments.
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "../common/arguments.hpp"
#include "../common/whole_file.hpp"
#include "report.hpp"

namespace {

constexpr const char* kUsage =
    "usage: dda_verify_paper --out DIR [--smoke] [--closed-form-only]\n"
    "  --out DIR  write report.md and the CSVs into DIR (created if missing)\n"
    "  --smoke    a short run for CI (few steps; original, local_frame, finite_rotation)\n"
    "  --closed-form-only  only the sliding block's and the plastic specimen's sweeps\n"
    "             (speed_incline.csv, speed_plastic.csv and their report.md sections)\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace dda::paper;
  Options opt;
  std::string out;
  if (const auto stop = dda::verification::parse_arguments(argc, argv, "dda_verify_paper", kUsage, out,
                                                           {{"--smoke", &opt.smoke}, {"--closed-form-only", &opt.closed_form_only}}))
    return *stop;
  opt.out = out;
  const auto start = std::chrono::steady_clock::now();
  try {
    std::filesystem::create_directories(opt.out);
    if (opt.closed_form_only) {
      std::cerr << "Speed against error: the sliding block and the plastic specimen...\n";
      const ClosedFormSpeed r = run_closed_form_speed(opt);
      write_closed_form_speed_csv(opt, r);
      const std::string report =
          "# Speed against error beyond rotation (dda_verify_paper --closed-form-only" +
          std::string(opt.smoke ? " --smoke" : "") + ")\n\n" + closed_form_speed_report(opt, r);
      dda::verification::WholeFile out(opt.out / "report.md");
      if (!(out << report)) {
        std::cerr << "dda_verify_paper: cannot write " << (opt.out / "report.md").string() << '\n';
        return 1;
      }
      out.finish();  // a failed close or rename throws "cannot write ...", reported below
      std::cout << report;
      return 0;
    }
    AllResults all;
    std::cerr << "Table 1: the falling octagon...\n";
    all.falling = run_falling(opt);
    write_falling_csv(opt, all.falling);
    std::cerr << "Tables 2 and 3: the swinging octagon...\n";
    all.swinging = run_swinging(opt);
    write_swinging_csv(opt, all.swinging);
    std::cerr << "Speed against error...\n";
    all.speed = run_speed(opt);
    write_speed_csv(opt, all.speed);
    std::cerr << "Stress under rotation and the energy gain...\n";
    all.rotation = run_rotation_study(opt);
    write_rotation_csv(opt, all.rotation);
    all.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string report = full_report(opt, all);
    dda::verification::WholeFile out(opt.out / "report.md");
    if (!(out << report)) {
      std::cerr << "dda_verify_paper: cannot write " << (opt.out / "report.md").string() << '\n';
      return 1;
    }
    out.finish();  // a failed close or rename throws "cannot write ...", reported below
    std::cout << report;
  } catch (const std::exception& e) {
    std::cerr << "dda_verify_paper: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
