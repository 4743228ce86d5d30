// The Python module `dda` (docs/python.md): run a scene a few steps at a time and read its
// state as numpy arrays, cut a model, find a factor of safety. A thin layer over the
// library: scenes and models go through the same readers as the command line's, errors
// are Python exceptions carrying the same located messages, long calls release the GIL and
// stop on Ctrl-C (python/signal_watch.hpp).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "cutting/model.hpp"
#include "io/cut_scene.hpp"
#include "io/input_error.hpp"
#include "io/output.hpp"
#include "python/factor_bindings.hpp"
#include "python/python_input.hpp"
#include "python/signal_watch.hpp"
#include "python/simulation.hpp"
#include "python/world_arrays.hpp"

namespace py = pybind11;
using namespace dda;
using namespace dda::python;

namespace {

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
