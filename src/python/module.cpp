// The Python module `dda` (docs/python.md): run a scene a few steps at a time and read its
// state as numpy arrays, cut a model, find a factor of safety. A thin layer over the
// library: scenes and models go through the same readers as the command line's, errors
// are Python exceptions carrying the same located messages, long calls release the GIL and
// stop on Ctrl-C (python/signal_watch.hpp).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "cutting/model.hpp"
#include "io/cut_scene.hpp"
#include "io/input_error.hpp"
#include "io/output.hpp"
#include "python/factor_study.hpp"
#include "python/python_input.hpp"
#include "python/signal_watch.hpp"
#include "python/simulation.hpp"
#include "python/world_arrays.hpp"
#include "solver/step.hpp"

namespace py = pybind11;
using namespace dda;
using namespace dda::python;

namespace {

// Passes the scene's warnings (an unused joint material, ...) to Python's warnings.
void warn_about(const Scene& scene) {
  const py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& w : scene.warnings) warn(w, py::module_::import("builtins").attr("UserWarning"), 2);
}

// A Simulation works without the GIL: a second Python thread could call it while it runs.
// One call at a time; the other is refused (a RuntimeError) rather than left to race.
class OneCallAtATime {
 public:
  explicit OneCallAtATime(std::atomic<bool>& busy) : busy_(busy) {
    if (busy_.exchange(true)) throw std::runtime_error("this Simulation is running in another thread");
  }
  ~OneCallAtATime() { busy_ = false; }
  OneCallAtATime(const OneCallAtATime&) = delete;
  OneCallAtATime& operator=(const OneCallAtATime&) = delete;

 private:
  std::atomic<bool>& busy_;
};

// A reader of the simulation's state, refused while another thread steps it.
template <class Read>
auto guarded(Read read) {
  return [read](const Simulation& sim) {
    const OneCallAtATime guard(sim.busy);
    return read(sim);
  };
}

std::unique_ptr<Simulation> make_simulation(const py::object& scene_object) {
  Scene scene = scene_from_python(scene_object);
  warn_about(scene);
  std::unique_ptr<Simulation> sim;
  {
    py::gil_scoped_release release;
    sim = std::make_unique<Simulation>(std::move(scene));
  }
  return sim;
}

py::dict stats_dict(const Simulation& sim) {
  const RunStats& s = sim.stats();
  py::dict d;
  d["steps"] = s.steps;
  d["cut_steps"] = s.cut_steps;
  d["iterations"] = s.iterations;
  d["open_close_max"] = s.open_close_max;
  d["contacts_max"] = s.contacts_max;
  d["bonds_broken"] = s.bonds_broken;
  d["deepest_penetration"] = s.deepest_penetration;
  d["largest_normal_force"] = s.largest_normal_force;
  d["smallest_time_step"] = s.smallest_time_step;
  d["largest_time_step"] = s.largest_time_step;
  d["wall_time_s"] = sim.wall_time_s();
  return d;
}

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

py::object cut(const py::object& model_object) {
  const Model model = model_from_python(model_object);
  std::string text;
  call_on_worker([&](const StopQuery&) {
    // CGAL's arrangement has no place to stop: Ctrl-C is raised once the cut is done.
    // The scene is a dict, whose file names (a base_motion record) are read relative to the
    // current directory: named as for a scene file there.
    const CutModel blocks = cut_model(model.spec);
    text = scene_text(cut_scene(model, blocks, kSceneDictName).scene);
    read_back_cut_scene(text, kSceneDictName, model.source);
  });
  return json_loads(text);
}

// dda.run(scene, out=None, until=None): the scene run to its end (or to `until`), written
// into `out` as `dda run --out` writes it when given.
std::unique_ptr<Simulation> run_scene(const py::object& scene_object, const py::object& out,
                                      std::optional<double> until) {
  std::unique_ptr<Simulation> sim = make_simulation(scene_object);
  std::optional<OutputWriter> writer;
  if (!out.is_none()) {
    const std::string dir = py::str(py::module_::import("os").attr("fspath")(out));
    if (dir.empty()) throw InputError("run: out is empty; give a directory");
    writer.emplace(dir, sim->scene());
  }
  call_on_this_thread([&](const StopQuery& stop) { sim->run(until, stop, writer ? &*writer : nullptr); });
  return sim;
}

}  // namespace

PYBIND11_MODULE(dda, m) {
  m.doc() = "Two-dimensional Discontinuous Deformation Analysis (docs/python.md)";
  m.attr("__version__") = DDA_VERSION;

  // Bad input: the command line's exit 2, with its message. A ValueError, as Python's
  // own functions raise for a value they cannot take.
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  // A step that failed (the command line's exit 3): a RuntimeError.
  static py::exception<DivergedRun> diverged_error(m, "DivergedError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const DivergedRun& e) {
      diverged_error(e.what());
    }
  });

  py::class_<Simulation>(m, "Simulation", "A scene's run, advanced a few steps at a time")
      .def(py::init(&make_simulation), py::arg("scene"),
           "Reads the scene (a path or a dict of its keys) and builds its world at t = 0")
      .def(
          "step",
          [](Simulation& sim, int n) {
            const OneCallAtATime guard(sim.busy);
            int made = 0;
            call_on_this_thread([&](const StopQuery& stop) { made = sim.step(n, stop); });
            return made;
          },
          py::arg("n") = 1, "Advances n steps (fewer at the scene's end); returns the steps made")
      .def(
          "run",
          [](Simulation& sim, std::optional<double> until) {
            const OneCallAtATime guard(sim.busy);
            int made = 0;
            call_on_this_thread([&](const StopQuery& stop) { made = sim.run(until, stop); });
            return made;
          },
          py::arg("until") = py::none(),
          "Steps to time `until` (s; the first step at or past it) or to the scene's end; "
          "returns the steps made")
      .def_property_readonly("time", guarded([](const Simulation& sim) { return sim.world().time; }),
                             "Simulated time (s)")
      .def_property_readonly("step_count", guarded([](const Simulation& sim) { return sim.world().step; }),
                             "Completed steps")
      .def_property_readonly("finished", &Simulation::finished, "The scene's end reached")
      .def_property_readonly("block_count", [](const Simulation& sim) { return sim.world().blocks.size(); })
      .def_property_readonly(
          "materials",
          [](const Simulation& sim) {
            py::list names;
            for (const Material& mat : sim.scene().materials) names.append(mat.name);
            return names;
          },
          "The scene's material names, indexed by blocks()['material']")
      .def("blocks", guarded([](const Simulation& sim) { return block_arrays(sim.world()); }),
           "The blocks' state as numpy arrays (docs/python.md)")
      .def("block_vertices",
           [](const Simulation& sim, long i) {
             const OneCallAtATime guard(sim.busy);
             return block_vertices(sim.world(), i);
           },
           py::arg("i"), "Block i's vertices now, (m, 2) in metres")
      .def("contacts", guarded([](const Simulation& sim) { return contact_arrays(sim.world()); }),
           "The contacts of the last step as numpy arrays")
      .def("energy", guarded([](const Simulation& sim) { return energy_terms(sim.world()); }),
           "The energy account's terms (J/m)")
      .def("monitors", guarded([](const Simulation& sim) { return monitor_arrays(sim.world()); }),
           "The monitoring points: names, position, displacement, velocity")
      .def("bolts", guarded([](const Simulation& sim) { return bolt_arrays(sim.world()); }),
           "The bolts: names, force, plastic extension, broken, length")
      .def("stats", guarded(&stats_dict), "What the run has counted: steps, cut steps, solves, wall time")
      .def("__repr__", [](const Simulation& sim) {
        return "<dda.Simulation of " + std::to_string(sim.world().blocks.size()) + " blocks at step " +
               std::to_string(sim.world().step) + ", t = " + std::string(py::str(py::float_(sim.world().time))) +
               " s>";
      });

  m.def("run", &run_scene, py::arg("scene"), py::arg("out") = py::none(), py::arg("until") = py::none(),
        "Runs a scene to its end (or to `until`, s); with `out`, writes what `dda run --out` "
        "writes (no pictures). Returns the Simulation");
  m.def("cut", &cut, py::arg("model"),
        "Cuts a model (a path or a dict) into blocks: the scene `dda cut` writes, as a dict");
  m.def("fos", &fos, py::arg("scene"),
        "Factor of safety by strength reduction (dda fos without its report): a dict with "
        "found, factor, bracket, message, trials, settings, consolidation. Keywords: "
        "tolerance, min_factor, max_factor, failure_displacement, trial_time, "
        "dynamic_coefficient, reduce_materials, jobs, consolidation_factor, seismic_coefficient");
  m.def("fos_samples", &fos_samples, py::arg("scene"), py::arg("samples"), py::arg("seed") = 0,
        py::arg("at_factor") = py::none(),
        "The probabilistic factor (dda fos --samples): the scene's random_strengths drawn "
        "`samples` times; with at_factor, one trial each at that F. Keywords as for fos");
}
