// dda_verify_slope --out DIR [--smoke] [--case NAME]... [--jobs N] [--verbose]: the factor of
// safety of Hoek & Bray's slope examples by DDA strength reduction beside their
// limit-equilibrium closed forms; writes slope.csv, report.json, report.md and the
// mechanisms' outlines into DIR and prints the report. Exit codes: 0 done (a case off its
// tolerance or skipped is a result in the report, not a failure); 1 a case could not run or
// the output could not be written; 2 bad arguments.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "report.hpp"
#include "slope_cases.hpp"
#include "slope_run.hpp"
#include "studies/settings_spread.hpp"
#include "studies/strength_reduction.hpp"

namespace {

constexpr const char* kUsage =
    "usage: dda_verify_slope --out DIR [--smoke] [--case NAME]... [--jobs N] [--dynamic] [--verbose] [--spread]\n"
    "  --out DIR    write slope.csv, report.json, report.md, mechanism_*.json into DIR\n"
    "  --smoke      the CI subset (planar_c10, hoek_bray_dry) with search tolerance 0.05\n"
    "  --case NAME  run only this case (repeatable); --list shows the names\n"
    "  --jobs N     trials at once (default 2)\n"
    "  --dynamic    dynamic trials (dynamic coefficient 1) instead of the default static ones\n"
    "  --verbose    a line per trial on standard error\n"
    "  --spread     also run every case at dt / 5, dt x 5, penalty / 10 and penalty x 10, and\n"
    "               report the spread of the five factors\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace dda::slope;
  using dda::SpreadFactor;
  using dda::SpreadSetting;
  using dda::judge_spread;
  using dda::kSpreadSettings;
  std::filesystem::path out;
  std::vector<std::string> only;
  bool smoke = false, verbose = false, list = false, spread = false;
  RunOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--smoke") {
      smoke = true;
    } else if (arg == "--verbose") {
      verbose = true;
    } else if (arg == "--list") {
      list = true;
    } else if (arg == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (arg == "--case" && i + 1 < argc) {
      only.emplace_back(argv[++i]);
    } else if (arg == "--jobs" && i + 1 < argc) {
      options.jobs = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--spread") {
      spread = true;
    } else if (arg == "--dynamic") {
      options.dynamic_coefficient = 1.0;
    } else if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    } else {
      std::cerr << "dda_verify_slope: unexpected argument \"" << arg << "\"\n" << kUsage;
      return 2;
    }
  }
  const double a_det = dda::FosSettings{}.detect_acceleration;
  std::vector<SlopeCase> cases = all_cases(a_det);
  if (list) {
    for (const SlopeCase& c : cases) std::cout << c.name << ": " << c.title << '\n';
    return 0;
  }
  if (out.empty()) {
    std::cerr << "dda_verify_slope: --out DIR is required\n" << kUsage;
    return 2;
  }
  for (const std::string& name : only) {
    if (std::none_of(cases.begin(), cases.end(), [&](const SlopeCase& c) { return c.name == name; })) {
      std::cerr << "dda_verify_slope: unknown case \"" << name << "\" (--list shows them)\n";
      return 2;
    }
  }
  std::erase_if(cases, [&](const SlopeCase& c) {
    if (!only.empty()) return std::find(only.begin(), only.end(), c.name) == only.end();
    return smoke && !c.in_smoke;
  });
  // The smoke run's coarser bracket: fewer trials, for CI (README "Smoke").
  if (smoke) options.tolerance = 0.05;
  const auto start = std::chrono::steady_clock::now();
  try {
    std::filesystem::create_directories(out);
    std::vector<CaseResult> results;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      std::cerr << "[" << i + 1 << "/" << cases.size() << "] " << cases[i].name << ": "
                << cases[i].title << "...\n";
      auto progress = [&](const std::string& line) {
        if (verbose) std::cerr << line << '\n';
      };
      results.push_back(run_case(cases[i], options, progress));
      if (spread && results.back().found) {
        CaseResult& r = results.back();
        std::vector<SpreadFactor> found;
        for (const SpreadSetting& setting : kSpreadSettings) {
          RunOptions varied = options;
          varied.time_step_scale = setting.time_step_scale;
          varied.penalty_scale = setting.penalty_scale;
          const CaseResult v = run_case(cases[i], varied, progress);
          r.spread_factors.push_back(v.found ? v.factor : 0.0);
          SpreadFactor f;
          f.setting = setting.name;
          f.found = v.found;
          f.factor = v.factor;
          f.last_stable = v.last_stable;
          f.first_failing = v.first_failing;
          found.push_back(f);
          std::cerr << "  " << setting.name << ": " << (v.found ? std::to_string(v.factor) : v.note) << '\n';
        }
        r.spread = judge_spread(r.factor, r.first_failing - r.last_stable, std::move(found)).spread;
      }
      std::cerr << "[" << i + 1 << "/" << cases.size() << "] " << case_line(cases[i], results.back()) << '\n';
    }
    RunInfo info;
    info.smoke = smoke;
    info.tolerance = options.tolerance;
    info.jobs = options.jobs;
    info.dynamic_coefficient = options.dynamic_coefficient;
    info.spread = spread;
    info.detect_acceleration = a_det;
    info.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << write_reports(out, info, cases, results);
  } catch (const std::exception& e) {
    std::cerr << "dda_verify_slope: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
