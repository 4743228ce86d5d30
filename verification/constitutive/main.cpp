// dda_verify_constitutive --out DIR [--smoke]: the iso-error maps of the Mohr-Coulomb and
// Drucker-Prager return maps; writes one CSV per map, maps.csv and report.md into
// DIR and prints the report. Exit codes: 0 done (large errors are results, not failures);
// 1 the output could not be written; 2 bad arguments.
#include <chrono>
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
    "usage: dda_verify_constitutive --out DIR [--smoke]\n"
    "  --out DIR  write report.md, maps.csv and one CSV per map into DIR (created if missing)\n"
    "  --smoke    a 5 x 5 grid per map, for CI (the full run has 41 x 41)\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace dda::constitutive;
  Options opt;
  std::string out;
  if (const auto stop = dda::verification::parse_arguments(argc, argv, "dda_verify_constitutive", kUsage, out,
                                                           {{"--smoke", &opt.smoke}}))
    return *stop;
  opt.out = out;
  if (opt.smoke) {
    opt.n = 5;
    opt.min_timing_s = 0.0;
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    std::filesystem::create_directories(opt.out);
    std::vector<MapResult> maps;
    std::vector<MapSummary> summaries;
    for (const MapSpec& spec : make_maps()) {
      std::cerr << spec.name << "...\n";
      maps.push_back(compute_map(spec, opt.n, opt.substeps, opt.min_timing_s));
      summaries.push_back(summarise(maps.back()));
      write_map_csv(opt.out, maps.back());
    }
    write_summary_csv(opt.out, maps, summaries);
    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string report = full_report(opt, maps, summaries, wall_s);
    dda::verification::WholeFile out(opt.out / "report.md");
    if (!(out << report)) {
      std::cerr << "dda_verify_constitutive: cannot write " << (opt.out / "report.md").string()
                << '\n';
      return 1;
    }
    out.finish();  // a failed close or rename throws "cannot write ...", reported below
    std::cout << report;
  } catch (const std::exception& e) {
    std::cerr << "dda_verify_constitutive: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
