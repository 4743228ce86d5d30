// Scenes and models given from Python: a path (str or os.PathLike) read as the command line
// reads the file, or a dict serialised to JSON text and read by the same reader, so that a
// bad one raises the same located message ("scene dict: blocks[1].vertices: ...").
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "io/model_reader.hpp"
#include "solver/scene.hpp"

namespace dda::python {

// What a dict is called in messages, where a file would be named by its path.
inline constexpr const char* kSceneDictName = "scene dict";
inline constexpr const char* kModelDictName = "model dict";

// JSON text of a dict (or list): numpy numbers and arrays become JSON numbers and arrays.
// Throws InputError (naming `what`) for an object JSON cannot hold.
std::string json_text(const pybind11::handle& value, const std::string& what);

// Throws InputError for anything but a path or a dict, and as the readers do.
Scene scene_from_python(const pybind11::handle& scene);
Model model_from_python(const pybind11::handle& model);

// Passes the scene's warnings (an unused joint material, ...) to Python's warnings, as
// UserWarning.
void warn_about(const Scene& scene);

// Python's json.loads of a JSON text: a dict for an object.
pybind11::object json_loads(const std::string& text);

}  // namespace dda::python
