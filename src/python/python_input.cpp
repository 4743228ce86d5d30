#include "python/python_input.hpp"

#include "io/input_error.hpp"
#include "io/scene_reader.hpp"

namespace py = pybind11;

namespace dda::python {
namespace {

bool is_path(const py::handle& value) {
  const py::object path_like = py::module_::import("os").attr("PathLike");
  return py::isinstance<py::str>(value) || py::isinstance(value, path_like);
}

std::string path_text(const py::handle& value) {
  return py::str(py::module_::import("os").attr("fspath")(value));
}

}  // namespace

std::string json_text(const py::handle& value, const std::string& what) {
  // numpy's numbers and arrays (and anything else with tolist) as the lists they hold.
  const py::cpp_function as_plain([](const py::object& o) -> py::object {
    if (py::hasattr(o, "tolist")) return o.attr("tolist")();
    throw py::type_error("not JSON: " + std::string(py::str(py::type::of(o).attr("__name__"))));
  });
  try {
    return py::str(py::module_::import("json").attr("dumps")(value, py::arg("default") = as_plain));
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_TypeError) && !e.matches(PyExc_ValueError)) throw;
    throw InputError(what + ": cannot be written as JSON (" + std::string(py::str(e.value())) + ")");
  }
}

void warn_about(const Scene& scene) {
  const py::object warn = py::module_::import("warnings").attr("warn");
  for (const std::string& w : scene.warnings) warn(w, py::module_::import("builtins").attr("UserWarning"), 2);
}

py::object json_loads(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

Scene scene_from_python(const py::handle& scene) {
  if (is_path(scene)) return read_scene_file(path_text(scene));
  if (py::isinstance<py::dict>(scene)) {
    return parse_scene_text(json_text(scene, kSceneDictName), kSceneDictName);
  }
  throw InputError("scene: give a path to a scene file or a dict of the scene's keys "
                   "(docs/scene-format.md), not a " +
                   std::string(py::str(py::type::of(scene).attr("__name__"))));
}

Model model_from_python(const py::handle& model) {
  if (is_path(model)) return read_model_file(path_text(model));
  if (py::isinstance<py::dict>(model)) {
    return parse_model_text(json_text(model, kModelDictName), kModelDictName);
  }
  throw InputError("model: give a path to a model file or a dict of the model's keys "
                   "(docs/model-format.md), not a " +
                   std::string(py::str(py::type::of(model).attr("__name__"))));
}

}  // namespace dda::python
