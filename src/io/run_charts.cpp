#include "io/run_charts.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/colour_maps.hpp"

namespace dda {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& file, const std::string& what) {
  throw std::runtime_error("plot: " + file.string() + ": " + what);
}

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  int column(const std::string& name, const fs::path& file) const {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) fail(file, "no column \"" + name + "\"");
    return static_cast<int>(it - header.begin());
  }
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream s(line);
  while (std::getline(s, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// The header and rows of a CSV file io/output wrote. A row with more fields than the header
// (a monitor name holding commas) keeps its extra fields joined into the third.
Csv read_csv(const fs::path& file) {
  std::ifstream in(file);
  if (!in) fail(file, "cannot be read");
  Csv c;
  std::string line;
  if (!std::getline(in, line)) fail(file, "is empty");
  c.header = split(line);
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> f = split(line);
    while (f.size() > c.header.size() && f.size() > 3) {
      f[2] += "," + f[3];
      f.erase(f.begin() + 3);
    }
    if (f.size() != c.header.size()) continue;  // a row cut short by a stopped run
    c.rows.push_back(std::move(f));
  }
  return c;
}

double number(const std::string& s, const fs::path& file) {
  try {
    std::size_t used = 0;
    const double v = std::stod(s, &used);
    if (used == s.size()) return v;
  } catch (const std::exception&) {
  }
  fail(file, "\"" + s + "\" is not a number");
}

}  // namespace

ChartOptions energy_chart(const fs::path& history_csv) {
  const Csv c = read_csv(history_csv);
  const int step = c.column("step", history_csv), time = c.column("time", history_csv);
  const char* terms[] = {"kinetic", "potential", "strain_energy", "contact_energy", "load_work",
                         "friction_dissipation", "plastic_dissipation", "damping_dissipation",
                         "multiplier_work", "energy_remainder"};
  std::vector<int> columns;
  for (const char* t : terms) columns.push_back(c.column(t, history_csv));
  std::vector<double> times;
  std::vector<std::vector<double>> values(columns.size());
  std::string last_step;
  for (const auto& row : c.rows) {
    if (row[static_cast<std::size_t>(step)] == last_step) continue;  // one row per step
    last_step = row[static_cast<std::size_t>(step)];
    times.push_back(number(row[static_cast<std::size_t>(time)], history_csv));
    for (std::size_t k = 0; k < columns.size(); ++k)
      values[k].push_back(number(row[static_cast<std::size_t>(columns[k])], history_csv));
  }
  if (times.empty()) fail(history_csv, "has no rows");
  ChartOptions o;
  o.title = "energy account";
  o.x_label = "time (s)";
  o.y_label = "energy (J/m)";
  for (std::size_t k = 0; k < columns.size(); ++k) {
    std::vector<double> y = values[k];
    std::string label = terms[k];
    if (label == "potential") {  // its change: the potential's zero is arbitrary
      const double y0 = y.front();
      for (double& v : y) v -= y0;
      label = "potential change";
    }
    const bool remainder = label == "energy_remainder";
    if (!remainder && std::all_of(y.begin(), y.end(), [](double v) { return v == 0.0; })) continue;
    ChartSeries s;
    s.label = label;
    s.x = times;
    s.y = std::move(y);
    s.colour = remainder ? Rgb{0, 0, 0} : category_colour(static_cast<int>(k));
    s.line_width = remainder ? 3.0 : 2.0;
    o.series.push_back(std::move(s));
  }
  return o;
}

ChartOptions monitors_chart(const fs::path& monitors_csv) {
  const Csv c = read_csv(monitors_csv);
  const int time = c.column("time", monitors_csv), name = c.column("monitor", monitors_csv);
  const int ux = c.column("ux", monitors_csv), uy = c.column("uy", monitors_csv);
  std::vector<std::string> names;
  std::map<std::string, std::pair<ChartSeries, ChartSeries>> series;
  for (const auto& row : c.rows) {
    const std::string& m = row[static_cast<std::size_t>(name)];
    if (!series.count(m)) names.push_back(m);
    auto& [sx, sy] = series[m];
    const double t = number(row[static_cast<std::size_t>(time)], monitors_csv);
    sx.x.push_back(t);
    sx.y.push_back(number(row[static_cast<std::size_t>(ux)], monitors_csv));
    sy.x.push_back(t);
    sy.y.push_back(number(row[static_cast<std::size_t>(uy)], monitors_csv));
  }
  if (names.empty()) fail(monitors_csv, "has no rows");
  ChartOptions o;
  o.title = "monitoring points";
  o.x_label = "time (s)";
  o.y_label = "displacement (m): ux thick, uy thin";
  for (std::size_t k = 0; k < names.size(); ++k) {
    auto& [sx, sy] = series[names[k]];
    sx.label = names[k] + " ux";
    sy.label = names[k] + " uy";
    sx.colour = sy.colour = category_colour(static_cast<int>(k));
    sx.line_width = 3.0;
    sy.line_width = 1.0;
    o.series.push_back(std::move(sx));
    o.series.push_back(std::move(sy));
  }
  return o;
}

}  // namespace dda
