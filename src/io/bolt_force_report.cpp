#include "io/bolt_force_report.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/text_file.hpp"

namespace dda {

void write_bolt_force_report(const std::string& out_dir, const std::string& scene_path,
                             const BoltForceSearch& search, double wall_time_s) {
  nlohmann::ordered_json trials = nlohmann::ordered_json::array();
  for (const BoltForceTrial& t : search.trials) {
    trials.push_back({{"force", t.force},
                      {"stable", t.stable},
                      {"verdict", t.verdict},
                      {"largest_displacement", t.largest_displacement}});
  }
  const nlohmann::ordered_json report = {
      {"scene", scene_path},
      {"target_factor", search.target_factor},
      {"found", search.found},
      // N/m, each bolt: the smallest force tried whose trial at the target stood, and the
      // largest whose trial failed (the bracket; 0 when none failed).
      {"bolt_force", search.found ? nlohmann::ordered_json(search.force) : nlohmann::ordered_json()},
      {"failing_force", search.failing_force},
      {"message", search.message},
      {"interrupted", search.interrupted},
      {"wall_time_s", wall_time_s},
      {"trials", trials}};
  write_text_file((std::filesystem::path(out_dir) / "bolt_force.json").string(), report.dump(2) + "\n");
}

}  // namespace dda
