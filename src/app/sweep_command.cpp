#include "app/sweep_command.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>

#include "app/fos_command.hpp"
#include "app/interrupt.hpp"
#include "app/ranks.hpp"
#include "io/input_error.hpp"
#include "io/json_input.hpp"
#include "io/output_file.hpp"
#include "io/scene_reader.hpp"
#include "io/sweep_spec.hpp"

namespace dda {
namespace {

namespace fs = std::filesystem;

// A CSV cell of a variant's value: numbers as the shortest text that reads back the same,
// strings in double quotes (inner ones doubled), as a spreadsheet reads them.
std::string cell(const nlohmann::json& v) {
  if (v.is_number()) return input::format_number(v.get<double>());
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  std::string out = "\"";
  for (char c : v.get<std::string>()) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string number_cell(const nlohmann::json& report, const char* key) {
  const auto it = report.find(key);
  return it != report.end() && it->is_number() ? input::format_number(it->get<double>()) : "";
}

// The result columns of a variant that ran, from its report.json.
std::string result_cells(const fs::path& report_path) {
  std::ifstream in(report_path);
  if (!in) return ",,,,";
  const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  if (report.is_discarded()) return ",,,,";
  std::string row = number_cell(report, "factor_of_safety");
  const auto bracket = report.find("bracket");
  if (bracket != report.end() && bracket->is_array() && bracket->size() == 2) {
    row.append(",").append(input::format_number((*bracket)[0].get<double>()));
    row.append(",").append(input::format_number((*bracket)[1].get<double>()));
  } else {
    row += ",,";
  }
  const auto p = report.find("probabilistic");
  row += ",";
  if (p != report.end()) {
    row.append(number_cell(*p, "probability_of_failure")).append(",");
    row.append(number_cell(*p, "samples_judged"));
  } else {
    row += ",";
  }
  return row;
}

const char* status_of(int code) {
  switch (code) {
    case 0: return "done";
    case 1: return "output error";
    case 2: return "input error";
    case 3: return "no factor";
    default: return "interrupted";
  }
}

}  // namespace

int sweep_command(const std::string& sweep_path, const std::string& out_dir) {
  if (sweep_path.empty()) {
    throw InputError("sweep: no sweep file given (dda sweep SWEEP.json --out DIR; see docs/sweep.md)");
  }
  const SweepSpec spec = read_sweep_file(sweep_path);
  fs::path scene_file = spec.scene_path;
  if (scene_file.is_relative()) scene_file = fs::path(sweep_path).parent_path() / scene_file;
  const nlohmann::json scene =
      input::parse_strict_json(input::read_input_file(scene_file.string(), "a scene file"),
                               scene_file.string());
  // Every variant's scene read before any runs: a bad value is an error now, with its
  // variant named, not after hours of the others.
  std::vector<std::string> texts;
  for (std::size_t v = 0; v < spec.variants.size(); ++v) {
    texts.push_back(variant_scene(scene, spec, v).dump(2) + "\n");
    parse_scene_text(texts.back(), sweep_path + ": " + variant_name(v) + " (scene " +
                                       scene_file.string() + ")");
  }
  if (is_root_rank()) prepare_output_directory(out_dir, {"sweep.csv"});

  FosSettings settings;
  settings.jobs = spec.fos.jobs;
  settings.tolerance = spec.fos.tolerance;
  settings.consolidation_factor = spec.fos.consolidation_factor;
  FosCommandOptions options;
  options.skip_limit_analysis = spec.fos.skip_limit_analysis;
  options.samples = spec.fos.samples;
  options.seed = spec.fos.seed;
  options.at_factor = spec.fos.at_factor;

  // Variant v runs on rank v % ranks, alone there (a search or samples of its own).
  const std::size_t ranks = static_cast<std::size_t>(rank_count());
  const std::size_t me = static_cast<std::size_t>(rank_index());
  std::string rows;
  for (std::size_t v = me; v < spec.variants.size(); v += ranks) {
    std::string row = variant_name(v);
    for (const nlohmann::json& value : spec.variants[v]) row.append(",").append(cell(value));
    const fs::path dir = fs::path(out_dir) / variant_name(v);
    int code = interrupted_exit_code();
    const bool started = interrupt_signal() == 0;  // after a signal the rest are not run
    if (started) {
      std::cerr << "dda: " << variant_name(v) << " of " << spec.variants.size() << "\n";
      fs::create_directories(dir);
      write_file_whole(dir / "scene.json", texts[v]);
      const SoloRank alone;
      try {
        code = fos_command((dir / "scene.json").string(), dir.string(), settings, options);
      } catch (const InputError& e) {
        std::cerr << "dda: " << variant_name(v) << ": error: " << e.what() << "\n";
        code = 2;
      } catch (const std::exception& e) {
        std::cerr << "dda: " << variant_name(v) << ": error: " << e.what() << "\n";
        code = 1;
      }
    }
    row.append(",").append(std::to_string(code));
    row.append(",").append(started ? status_of(code) : "not run");
    row.append(",").append(started ? result_cells(dir / "report.json") : std::string(",,,,"));
    row.append("\n");
    rows += row;
  }
  const std::vector<std::string> all = gather_to_root(rows);
  if (!is_root_rank()) return interrupt_signal() != 0 ? interrupted_exit_code() : 0;
  // Rows in variant order: rank r holds variants r, r + ranks, ...
  std::vector<std::vector<std::string>> by_rank(all.size());
  for (std::size_t r = 0; r < all.size(); ++r) {
    std::size_t at = 0;
    while (at < all[r].size()) {
      const std::size_t end = all[r].find('\n', at);
      by_rank[r].push_back(all[r].substr(at, end - at + 1));
      at = end + 1;
    }
  }
  std::string csv = "variant";
  for (const std::string& p : spec.pointers) csv.append(",").append(cell(p));
  csv += ",exit_code,status,factor_of_safety,last_stable,first_failing,probability_of_failure,"
         "samples_judged\n";
  for (std::size_t v = 0; v < spec.variants.size(); ++v) {
    const std::size_t r = v % all.size(), j = v / all.size();
    if (j < by_rank[r].size()) csv += by_rank[r][j];
  }
  write_file_whole(fs::path(out_dir) / "sweep.csv", csv);
  std::cerr << "dda: " << spec.variants.size() << " variants; " << out_dir << "/sweep.csv\n";
  return interrupt_signal() != 0 ? interrupted_exit_code() : 0;
}

}  // namespace dda
