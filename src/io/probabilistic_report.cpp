#include "io/probabilistic_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/printf_text.hpp"
#include "io/chart.hpp"

namespace dda {
namespace {

using json = nlohmann::json;

std::string general(double x) { return printf_text(x, "%.4g"); }

json bound_json(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

bool searching(const ProbabilisticResult& r) { return r.settings.at_factor <= 0.0; }

std::string variable_name(const RandomStrength& v) {
  std::string out = v.name;
  out += ".";
  out += strength_property_name(v.property);
  return out;
}

// Counts of `values` in `bins` equal bins over [lo, hi] (the top edge in the last bin).
std::vector<double> counts(const std::vector<double>& values, double lo, double hi, int bins) {
  std::vector<double> c(static_cast<std::size_t>(bins), 0.0);
  const double width = (hi - lo) / bins;
  for (double x : values) {
    int k = width > 0.0 ? static_cast<int>(std::floor((x - lo) / width)) : 0;
    k = std::clamp(k, 0, bins - 1);
    c[static_cast<std::size_t>(k)] += 1.0;
  }
  return c;
}

// A histogram as a step line: up at each bin's left edge, across, down at the last.
ChartSeries step_series(const std::vector<double>& c, double lo, double width, std::string label,
                        Rgb colour) {
  ChartSeries s;
  s.label = std::move(label);
  s.colour = colour;
  s.x.push_back(lo);
  s.y.push_back(0.0);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double left = lo + width * static_cast<double>(k);
    s.x.push_back(left);
    s.y.push_back(c[k]);
    s.x.push_back(left + width);
    s.y.push_back(c[k]);
  }
  s.x.push_back(lo + width * static_cast<double>(c.size()));
  s.y.push_back(0.0);
  return s;
}

// About sqrt(n) bins (a common rule for a first look), between 5 and 40.
int bin_count(std::size_t n) {
  return std::clamp(static_cast<int>(std::lround(std::sqrt(static_cast<double>(n)))), 5, 40);
}

}  // namespace

json probabilistic_json(const ProbabilisticResult& r, const RandomStrengths& spec) {
  const ProbabilisticSummary& s = r.summary;
  json variables = json::array();
  for (const RandomStrength& v : spec.variables) {
    variables.push_back({{"owner", strength_owner_name(v.owner)},
                         {"name", v.name},
                         {"property", strength_property_name(v.property)},
                         {"distribution", strength_distribution_name(v.distribution)},
                         {"mean", v.mean},
                         {"standard_deviation", v.standard_deviation},
                         {"min", bound_json(v.min)},
                         {"max", bound_json(v.max)}});
  }
  json correlations = json::array();
  for (const StrengthCorrelation& c : spec.correlations) {
    correlations.push_back({{"variables", {c.first, c.second}}, {"coefficient", c.coefficient}});
  }
  json samples = json::array();
  for (const SampleOutcome& o : r.samples) {
    if (!o.done) continue;
    json row = {{"index", o.index},
                {"values", o.values},
                {"verdict", o.failing ? "failing" : "stable"},
                {"why", o.verdict},
                {"trials", o.trials},
                {"steps", o.steps},
                {"wall_time_s", o.wall_time_s}};
    if (searching(r)) {
      row["factor"] = o.factor_found ? json(o.factor) : json(nullptr);
      row["bracket"] = o.factor_found ? json::array({o.last_stable, o.first_failing}) : json(nullptr);
      row["message"] = o.message;
    }
    samples.push_back(std::move(row));
  }
  json out = {{"mode", searching(r) ? "factor" : "verdict"},
              {"judged_at", r.judged_at},
              {"seed", r.settings.seed},
              {"samples_asked", r.settings.samples},
              {"samples_judged", s.judged},
              {"interrupted", r.interrupted},
              {"variables", variables},
              {"correlations", correlations},
              {"failing", s.failing},
              {"probability_of_failure", s.judged > 0 ? json(s.probability_of_failure) : json(nullptr)},
              {"confidence_interval",
               {{"level", 0.95}, {"method", "Wilson score"}, {"low", s.interval.low}, {"high", s.interval.high}}},
              {"samples", samples}};
  if (searching(r)) {
    out["factor"] = {{"count", s.factors},
                     {"mean", s.factors > 0 ? json(s.mean_factor) : json(nullptr)},
                     {"standard_deviation", s.factors > 1 ? json(s.factor_standard_deviation) : json(nullptr)},
                     {"min", s.factors > 0 ? json(s.min_factor) : json(nullptr)},
                     {"max", s.factors > 0 ? json(s.max_factor) : json(nullptr)},
                     {"above_range", s.above_range},
                     {"below_range", s.below_range}};
  }
  return out;
}

std::string probabilistic_line(const ProbabilisticResult& r) {
  const ProbabilisticSummary& s = r.summary;
  std::ostringstream line;
  line << "P(F < " << general(r.judged_at) << ") = " << general(s.probability_of_failure)
       << " (95 % Wilson interval " << general(s.interval.low) << " to " << general(s.interval.high)
       << ") over " << s.judged << " samples";
  if (searching(r) && s.factors > 0) {
    line << "; F mean " << general(s.mean_factor) << ", standard deviation "
         << general(s.factor_standard_deviation) << " over " << s.factors;
  }
  return line.str();
}

std::string probabilistic_markdown(const ProbabilisticResult& r, const RandomStrengths& spec) {
  const ProbabilisticSummary& s = r.summary;
  std::ostringstream md;
  md << "## Probabilistic factor of safety\n\n**" << probabilistic_line(r) << "**";
  if (r.interrupted) md << " (interrupted: " << s.judged << " of " << r.settings.samples << " samples judged)";
  md << ".\n\n";
  if (searching(r)) {
    md << "Each sample's factor by the strength-reduction search (one trial at a time); its "
          "trial at F = 1 gives its verdict.";
    if (s.above_range + s.below_range > 0) {
      md << " Without a factor: " << s.above_range << " samples stable up to the largest F tried, "
         << s.below_range << " failing down to the smallest (left out of the mean, counted in P).";
    }
  } else {
    md << "One trial per sample at F = " << general(r.judged_at) << ", its verdict.";
  }
  md << " Seed " << r.settings.seed << "; every sample starts from the same consolidation at the "
        "scene's own strengths.\n\n| variable | distribution | mean | standard deviation | min | max |\n"
        "|---|---|---|---|---|---|\n";
  for (const RandomStrength& v : spec.variables) {
    md << "| " << variable_name(v) << " | " << strength_distribution_name(v.distribution) << " | "
       << general(v.mean) << " | " << general(v.standard_deviation) << " | " << general(v.min)
       << " | " << general(v.max) << " |\n";
  }
  for (const StrengthCorrelation& c : spec.correlations) {
    md << "\nCorrelation " << general(c.coefficient) << " between "
       << variable_name(spec.variables[static_cast<std::size_t>(c.first)]) << " and "
       << variable_name(spec.variables[static_cast<std::size_t>(c.second)])
       << " (of the normals behind them).\n";
  }
  md << "\n| sample |";
  for (const RandomStrength& v : spec.variables) md << " " << variable_name(v) << " |";
  md << " verdict |" << (searching(r) ? " F |" : "") << "\n|---|";
  for (std::size_t i = 0; i < spec.variables.size(); ++i) md << "---|";
  md << "---|" << (searching(r) ? "---|" : "") << "\n";
  int rows = 0;
  for (const SampleOutcome& o : r.samples) {
    if (!o.done || rows++ >= 200) continue;
    md << "| " << o.index << " |";
    for (double x : o.values) md << " " << general(x) << " |";
    md << " " << (o.failing ? "failing" : "stable") << " |";
    if (searching(r)) md << " " << (o.factor_found ? general(o.factor) : "–") << " |";
    md << "\n";
  }
  if (s.judged > 200) md << "\n(The first 200 of " << s.judged << " samples; all in report.json.)\n";
  return md.str();
}

std::string write_probabilistic_chart(const std::filesystem::path& dir, const ProbabilisticResult& r,
                                      const RandomStrengths& spec) {
  ChartOptions chart;
  if (searching(r)) {
    std::vector<double> factors;
    for (const SampleOutcome& o : r.samples) {
      if (o.done && o.factor_found) factors.push_back(o.factor);
    }
    if (factors.empty()) return "";
    const auto [lo_it, hi_it] = std::minmax_element(factors.begin(), factors.end());
    double lo = *lo_it, hi = *hi_it;
    if (hi - lo < 1e-9) {
      lo -= 0.05;
      hi += 0.05;
    }
    const int bins = bin_count(factors.size());
    chart.series.push_back(step_series(counts(factors, lo, hi, bins), lo, (hi - lo) / bins,
                                       "samples", {31, 119, 180}));
    chart.vertical_lines.push_back({1.0, {200, 30, 30}, "F = 1"});
    chart.vertical_lines.push_back({r.summary.mean_factor, {0, 0, 0}, "mean"});
    chart.title = "Factors of safety of ";
    chart.title += std::to_string(factors.size());
    chart.title += " samples";
    chart.x_label = "factor of safety F";
    chart.y_label = "samples";
    write_chart((dir / "factors.png").string(), chart);
    return "factors.png";
  }
  if (spec.variables.empty()) return "";
  std::vector<double> stable, failing, all;
  for (const SampleOutcome& o : r.samples) {
    if (!o.done || o.values.empty()) continue;
    (o.failing ? failing : stable).push_back(o.values.front());
    all.push_back(o.values.front());
  }
  if (all.empty()) return "";
  const auto [lo_it, hi_it] = std::minmax_element(all.begin(), all.end());
  double lo = *lo_it, hi = *hi_it;
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
    lo -= 0.5;
    hi += 0.5;
  }
  const int bins = bin_count(all.size());
  const double width = (hi - lo) / bins;
  chart.series.push_back(step_series(counts(stable, lo, hi, bins), lo, width, "stable", {31, 119, 180}));
  chart.series.push_back(step_series(counts(failing, lo, hi, bins), lo, width, "failing", {214, 39, 40}));
  const std::string name = variable_name(spec.variables.front());
  chart.title = "Verdicts at F = ";
  chart.title += general(r.judged_at);
  chart.title += " against the drawn ";
  chart.title += name;
  chart.x_label = name;
  chart.y_label = "samples";
  write_chart((dir / "verdicts.png").string(), chart);
  return "verdicts.png";
}

}  // namespace dda
