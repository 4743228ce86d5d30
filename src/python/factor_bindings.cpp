#include "python/factor_bindings.hpp"

#include <pybind11/numpy.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "io/input_error.hpp"
#include "python/factor_study.hpp"
#include "python/python_input.hpp"
#include "python/signal_watch.hpp"

namespace py = pybind11;

namespace dda::python {
namespace {

// ---- factor-of-safety settings from keyword arguments, checked as the command line checks
// its options (the same ranges; a bad one is an InputError naming it) ----

double number_in(const py::handle& value, const char* name, double lo, double hi) {
  const double v = py::cast<double>(value);
  if (!std::isfinite(v) || v < lo || v > hi) {
    throw InputError(std::string("fos: ") + name + ": " + std::string(py::str(value)) +
                     " is not a finite number in [" + std::string(py::str(py::float_(lo))) + ", " +
                     std::string(py::str(py::float_(hi))) + "]");
  }
  return v;
}

double positive(const py::handle& value, const char* name) {
  const double v = py::cast<double>(value);
  if (!std::isfinite(v) || v <= 0.0) {
    throw InputError(std::string("fos: ") + name + ": " + std::string(py::str(value)) +
                     " is not a finite positive number");
  }
  return v;
}

FosSettings fos_settings(const py::kwargs& kw) {
  FosSettings s;
  for (const auto& [key, value] : kw) {
    const std::string k = py::str(key);
    if (value.is_none()) continue;  // the default
    if (k == "tolerance") s.tolerance = number_in(value, "tolerance", 1e-6, 1.0);
    else if (k == "min_factor") s.min_factor = number_in(value, "min_factor", 1e-3, 1.0);
    else if (k == "max_factor") s.max_factor = number_in(value, "max_factor", 1.0, 1e3);
    else if (k == "failure_displacement") s.failure_displacement = positive(value, "failure_displacement");
    else if (k == "trial_time") s.trial_time = positive(value, "trial_time");
    else if (k == "dynamic_coefficient") s.dynamic_coefficient = number_in(value, "dynamic_coefficient", 0.0, 1.0);
    else if (k == "reduce_materials") s.reduce_materials = py::cast<bool>(value);
    else if (k == "jobs") s.jobs = static_cast<int>(number_in(value, "jobs", 1, 64));
    else if (k == "consolidation_factor") s.consolidation_factor = number_in(value, "consolidation_factor", 1e-3, 1.0);
    else if (k == "seismic_coefficient") s.seismic_coefficient = number_in(value, "seismic_coefficient", -1.0, 1.0);
    else throw py::type_error("fos: unexpected keyword argument '" + k + "'");
  }
  return s;
}

py::dict settings_dict(const FosSettings& s) {
  py::dict d;
  d["tolerance"] = s.tolerance;
  d["min_factor"] = s.min_factor;
  d["max_factor"] = s.max_factor;
  d["failure_displacement"] = s.failure_displacement;
  d["trial_time"] = s.trial_time;
  d["dynamic_coefficient"] = s.dynamic_coefficient;
  d["reduce_materials"] = s.reduce_materials;
  d["jobs"] = s.jobs;
  d["consolidation_factor"] = s.consolidation_factor;
  d["seismic_coefficient"] = s.seismic_coefficient;
  return d;
}

py::dict consolidation_dict(const Consolidation& c) {
  py::dict d;
  d["steps"] = c.stats.steps;
  d["time"] = c.world.time;
  d["bonds_broken"] = c.stats.bonds_broken;
  d["settling_steps"] = c.settling.steps;
  d["at_rest"] = c.settling.at_rest;
  d["wall_time_s"] = c.stats.wall_time_s;
  return d;
}

py::dict trial_dict(const TrialResult& t) {
  py::dict d;
  d["factor"] = t.factor;
  d["stable"] = t.stable;
  d["verdict"] = t.verdict;
  d["displacement"] = t.largest_displacement;
  d["end_speed"] = t.end_speed;
  d["steps"] = t.steps;
  d["simulated_time"] = t.simulated_time;
  d["wall_time_s"] = t.wall_time_s;
  return d;
}

Scene read_for_factor(const py::object& scene_object, const FosSettings& settings) {
  Scene scene = with_seismic_coefficient(scene_from_python(scene_object), settings.seismic_coefficient);
  warn_about(scene);
  return scene;
}

}  // namespace

py::dict fos(const py::object& scene_object, const py::kwargs& kw) {
  const FosSettings given = fos_settings(kw);
  const Scene scene = read_for_factor(scene_object, given);
  std::optional<ConsolidatedScene> consolidated;
  FosResult result;
  call_on_worker([&](const StopQuery& stop) {
    consolidated = consolidate_for_factor(scene, given, stop);
    if (!consolidated->consolidation.stats.interrupted) result = search_factor(*consolidated, stop);
  });
  py::dict d;
  d["found"] = result.found;
  d["factor"] = result.found ? py::object(py::float_(result.factor_of_safety)) : py::object(py::none());
  if (result.found || result.has_bracket) {
    d["bracket"] = py::make_tuple(result.last_stable, result.first_failing);
  } else {
    d["bracket"] = py::none();
  }
  d["message"] = result.message;
  py::list trials;
  for (const TrialResult& t : result.trials) trials.append(trial_dict(t));
  d["trials"] = trials;
  d["settings"] = settings_dict(consolidated->settings);
  d["consolidation"] = consolidation_dict(consolidated->consolidation);
  return d;
}

py::dict fos_samples(const py::object& scene_object, long samples, std::uint64_t seed,
                     std::optional<double> at_factor, const py::kwargs& kw) {
  const FosSettings given = fos_settings(kw);
  const Scene scene = read_for_factor(scene_object, given);
  if (scene.random_strengths.variables.empty()) {
    throw InputError(scene.source + ": random_strengths: samples draw the strengths this key "
                     "describes, and the scene has none (docs/scene-format.md)");
  }
  ProbabilisticSettings p;
  p.samples = static_cast<long>(number_in(py::int_(samples), "samples", 1, 1e6));
  p.seed = seed;
  if (at_factor) p.at_factor = number_in(py::float_(*at_factor), "at_factor", 1e-3, 1e3);
  std::optional<ConsolidatedScene> consolidated;
  ProbabilisticResult result;
  call_on_worker([&](const StopQuery& stop) {
    consolidated = consolidate_for_factor(scene, given, stop);
    if (!consolidated->consolidation.stats.interrupted) result = sample_factors(scene, *consolidated, p, stop);
  });
  const ProbabilisticSummary& s = result.summary;
  py::dict d;
  d["judged_at"] = result.judged_at;
  d["judged"] = s.judged;
  d["failing"] = s.failing;
  d["probability_of_failure"] = s.probability_of_failure;
  d["interval"] = py::make_tuple(s.interval.low, s.interval.high);
  py::list names;
  for (const RandomStrength& v : scene.random_strengths.variables) {
    names.append(v.name + "." + strength_property_name(v.property));
  }
  d["variables"] = names;
  const std::size_t n = result.samples.size();
  const std::size_t width = scene.random_strengths.variables.size();
  py::array_t<double> values({n, width});
  py::array_t<bool> failing(static_cast<py::ssize_t>(n));
  py::array_t<double> factor(static_cast<py::ssize_t>(n));
  auto v = values.mutable_unchecked<2>();
  auto f = failing.mutable_unchecked<1>();
  auto F = factor.mutable_unchecked<1>();
  for (std::size_t i = 0; i < n; ++i) {
    const SampleOutcome& o = result.samples[i];
    const auto row = static_cast<py::ssize_t>(i);
    for (std::size_t k = 0; k < width; ++k) {
      v(row, static_cast<py::ssize_t>(k)) = k < o.values.size() ? o.values[k] : NAN;
    }
    f(row) = o.done && o.failing;
    F(row) = o.factor_found ? o.factor : NAN;
  }
  d["values"] = values;
  d["sample_failing"] = failing;
  d["sample_factor"] = factor;
  if (p.at_factor <= 0.0) {
    d["mean_factor"] = s.mean_factor;
    d["factor_standard_deviation"] = s.factor_standard_deviation;
  }
  d["settings"] = settings_dict(consolidated->settings);
  d["consolidation"] = consolidation_dict(consolidated->consolidation);
  return d;
}

}  // namespace dda::python
