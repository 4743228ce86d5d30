// dda.fos and dda.fos_samples: keyword settings checked as the command line checks its
// options, the study run without the GIL (python/factor_study.hpp), its result as a dict
// (docs/python.md, "dda.fos").
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>

namespace dda::python {

// Keywords: fos_settings's names (FosSettings, docs/python.md). Throws InputError for a value
// out of the command line's range, TypeError for an unknown keyword.
pybind11::dict fos(const pybind11::object& scene, const pybind11::kwargs& settings);
pybind11::dict fos_samples(const pybind11::object& scene, long samples, std::uint64_t seed,
                           std::optional<double> at_factor, const pybind11::kwargs& settings);

}  // namespace dda::python
