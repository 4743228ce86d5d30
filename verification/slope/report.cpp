#include "report.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "../common/format.hpp"
#include "../common/whole_file.hpp"

namespace dda::slope {
namespace {

using json = nlohmann::json;
using verification::fixed;
using verification::full;

// A case's published factor to its precision, or "–" for a case no one published.
std::string published(const SlopeCase& c) {
  return c.published > 0.0 ? fixed(c.published, c.published_decimals) : "–";
}

std::string status(const CaseResult& r) {
  if (r.skipped) return "skipped";
  if (!r.found) return "no factor";
  return r.pass ? "pass" : "FAIL";
}

json polygons(const std::vector<Polygon>& ps) {
  json out = json::array();
  for (const Polygon& p : ps) {
    json poly = json::array();
    for (const Vec2& v : p) poly.push_back({v.x(), v.y()});
    out.push_back(poly);
  }
  return out;
}

// Whole or not at all (verification/common/whole_file.hpp); throws "cannot write PATH".
void write_text(const std::filesystem::path& path, const std::string& text) {
  verification::write_whole_file(path, text);
}

json case_json(const SlopeCase& c, const CaseResult& r) {
  json j = {{"name", c.name},
            {"title", c.title},
            {"le_factor", c.le_factor},
            {"published_factor", c.published > 0.0 ? json(c.published) : json(nullptr)},
            {"resolution", c.resolution},
            {"status", status(r)},
            {"note", r.note},
            {"wall_time_s", r.wall_s},
            {"trials", r.trials}};
  if (c.limiting_friction > 0.0) j["limiting_friction_angle"] = c.limiting_friction;
  j["la_factor"] = r.la_found ? json(r.la_factor) : json(nullptr);
  if (!r.la_note.empty()) j["la_note"] = r.la_note;
  if (!r.spread_factors.empty()) {
    json settings = json::object();
    for (std::size_t k = 0; k < r.spread_factors.size(); ++k) {
      settings[kSpreadSettings[k].name] = r.spread_factors[k] > 0.0 ? json(r.spread_factors[k]) : json(nullptr);
    }
    j["spread_factors"] = settings;
    j["spread"] = r.spread;
  }
  if (r.found) {
    j["dda_factor"] = r.factor;
    j["bracket"] = {r.last_stable, r.first_failing};
    j["error"] = r.error;
    j["allowed_error"] = r.allowed;
    j["failure_displacement"] = r.failure_displacement;
    j["trial_time"] = r.trial_time;
  }
  if (!r.columns.empty()) {
    json cols = json::array();
    for (const ColumnMotion& m : r.columns) {
      cols.push_back({{"column", m.column}, {"rotation_deg", m.rotation_deg}, {"base_slip", m.base_slip},
                      {"top_move", m.top_move}, {"mode", m.mode}, {"le_mode", m.le_mode}});
    }
    j["columns"] = cols;
    j["interface_shares"] = r.interface_shares;
    j["le_mobilised_factor"] = r.le_mobilised;
    j["error_mobilised"] = r.error_mobilised;
  }
  if (!r.scan.empty()) {
    json scan = json::array();
    for (const auto& p : r.scan) scan.push_back({{"factor", p.factor}, {"stable", p.stable}, {"moved", p.moved}});
    j["scan"] = scan;
  }
  return j;
}

std::string markdown(const RunInfo& info, const std::vector<SlopeCase>& cases,
                     const std::vector<CaseResult>& results) {
  std::ostringstream md;
  md << "# Factor of safety: DDA strength reduction against limit equilibrium\n\n";
  md << (info.smoke ? "Smoke run (a subset, search tolerance " + fixed(info.tolerance, 3) +
                          "; not the verification itself).\n\n"
                    : "Full run, search tolerance " + fixed(info.tolerance, 3) + ".\n\n");
  md << (info.dynamic_coefficient >= 1.0 ? "Dynamic" : "Static") << " trials on " << info.jobs
     << " threads; a trial fails when a free block's centroid still moves at its end faster "
        "than a mechanism accelerating at detect_acceleration g ("
     << info.detect_acceleration << ") would (d/T in dynamic trials), or moves beyond the failure "
        "displacement. Allowed error = tolerance/2 + resolution (README \"Tolerances\"). Total "
        "wall time " << fixed(info.wall_s, 1) << " s.\n\n";
  md << "| case | LE | published | DDA | bracket | error | allowed | status | wall (s) | trials | limit analysis |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const SlopeCase& c = cases[i];
    const CaseResult& r = results[i];
    md << "| " << c.name << " | " << fixed(c.le_factor, 4) << " | " << published(c) << " | ";
    if (r.found) {
      md << fixed(r.factor, 4) << " | [" << fixed(r.last_stable, 4) << ", " << fixed(r.first_failing, 4)
         << "] | " << fixed(r.error, 4) << " | " << fixed(r.allowed, 4);
    } else {
      md << "- | - | - | " << fixed(r.allowed, 4);
    }
    md << " | " << status(r) << " | " << fixed(r.wall_s, 1) << " | " << r.trials << " | "
       << (r.la_found ? fixed(r.la_factor, 4) : std::string("-")) << " |\n";
  }
  md << "\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const SlopeCase& c = cases[i];
    const CaseResult& r = results[i];
    md << "- **" << c.name << "**: " << c.title << ".";
    if (c.limiting_friction > 0.0) {
      md << " Limiting friction angle " << fixed(c.limiting_friction, 3) << " deg (published 38.15).";
    }
    if (!r.note.empty()) md << " " << r.note;
    md << "\n";
  }
  if (info.spread) {
    md << "\n## The factor over dt and penalty (--spread)\n\n"
          "Each case again with its time step divided and multiplied by 5 and its penalty "
          "divided and multiplied by 10; spread = (max - min) / mean of the five factors.\n\n"
          "| case | own |";
    for (const SpreadSetting& setting : kSpreadSettings) md << " " << setting.name << " |";
    md << " spread |\n|---|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const CaseResult& r = results[i];
      if (r.spread_factors.empty()) continue;
      md << "| " << cases[i].name << " | " << fixed(r.factor, 4) << " |";
      for (double f : r.spread_factors) md << " " << (f > 0.0 ? fixed(f, 4) : std::string("-")) << " |";
      md << " " << fixed(100.0 * r.spread, 2) << " % |\n";
    }
  }
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const CaseResult& r = results[i];
    if (r.columns.empty()) continue;
    md << "\n## " << cases[i].name << ": columns at the first failing trial (F = "
       << fixed(r.first_failing, 4) << ")\n\n";
    md << "Share of the limiting friction on each column interface (n | n+1) at the end of that "
          "trial:";
    for (std::size_t k = 0; k < r.interface_shares.size(); ++k) {
      md << (k == 0 ? " " : ", ") << k + 1 << "|" << k + 2 << " " << fixed(r.interface_shares[k], 3);
    }
    md << ". The tabular method with these shares gives " << fixed(r.le_mobilised, 4)
       << "; DDA's factor differs from it by " << fixed(r.error_mobilised, 4) << " (allowed "
       << fixed(r.allowed, 4) << "), and from the tabular method with limiting friction on every "
          "interface by " << fixed(r.error, 4) << " (README \"Toppling: the interface that does not "
          "slip\").\n\n";
    md << "| column | rotation (deg) | base corner moved (m) | top corner moved (m) | DDA mode | LE mode |\n";
    md << "|---|---|---|---|---|---|\n";
    for (const ColumnMotion& m : r.columns) {
      md << "| " << m.column << " | " << fixed(m.rotation_deg, 5) << " | " << fixed(m.base_slip, 6)
         << " | " << fixed(m.top_move, 6) << " | " << m.mode << " | " << m.le_mode << " |\n";
    }
    if (r.scan.empty()) continue;
    md << "\nTrials every 0.05 below the search's first failing F (is the verdict monotone?):\n\n";
    md << "| F | verdict | largest displacement (m) |\n|---|---|---|\n";
    for (const auto& p : r.scan) {
      md << "| " << fixed(p.factor, 2) << " | " << (p.stable ? "stable" : "FAILS") << " | "
         << fixed(p.moved, 6) << " |\n";
    }
  }
  return md.str();
}

}  // namespace

std::string case_line(const SlopeCase& c, const CaseResult& r) {
  std::ostringstream s;
  s << c.name << ": LE " << fixed(c.le_factor, 4) << " (published " << published(c) << ")";
  if (r.skipped) {
    s << ", skipped: " << r.note;
  } else if (!r.found) {
    s << ", no DDA factor: " << r.note;
  } else {
    s << ", DDA " << fixed(r.factor, 4) << " [" << fixed(r.last_stable, 4) << ", "
      << fixed(r.first_failing, 4) << "], error " << fixed(r.error, 4) << " (allowed "
      << fixed(r.allowed, 4) << ") " << status(r);
  }
  s << ", " << fixed(r.wall_s, 1) << " s, " << r.trials << " trials";
  return s.str();
}

std::string write_reports(const std::filesystem::path& dir, const RunInfo& info,
                          const std::vector<SlopeCase>& cases, const std::vector<CaseResult>& results) {
  std::ostringstream csv;
  csv << "case,le_factor,published_factor,dda_factor,last_stable,first_failing,error,allowed_error,"
         "status,wall_time_s,trials,la_factor\n";
  json report = {{"smoke", info.smoke}, {"tolerance", info.tolerance}, {"jobs", info.jobs}, {"dynamic_coefficient", info.dynamic_coefficient},
                 {"detect_acceleration", info.detect_acceleration}, {"wall_time_s", info.wall_s},
                 {"cases", json::array()}};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const SlopeCase& c = cases[i];
    const CaseResult& r = results[i];
    csv << c.name << ',' << full(c.le_factor) << ',' << (c.published > 0.0 ? full(c.published) : "") << ',';
    if (r.found) {
      csv << full(r.factor) << ',' << full(r.last_stable) << ',' << full(r.first_failing) << ','
          << full(r.error) << ',';
    } else {
      csv << ",,,,";
    }
    csv << full(r.allowed) << ',' << status(r) << ',' << full(r.wall_s) << ',' << r.trials << ','
        << (r.la_found ? full(r.la_factor) : "") << '\n';
    report["cases"].push_back(case_json(c, r));
    if (!r.before.empty()) {
      const json mech = {{"case", c.name},           {"title", c.title},
                         {"le_factor", c.le_factor}, {"first_failing", r.first_failing},
                         {"fixed", r.fixed},         {"before", polygons(r.before)},
                         {"after", polygons(r.after)}};
      write_text(dir / ("mechanism_" + c.name + ".json"), mech.dump());
    }
  }
  const std::string md = markdown(info, cases, results);
  write_text(dir / "slope.csv", csv.str());
  write_text(dir / "report.json", report.dump(2) + "\n");
  write_text(dir / "report.md", md);
  return md;
}

}  // namespace dda::slope
