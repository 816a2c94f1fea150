#pragma once
/// \file bindings.hpp
/// The parts of the Python module, one `define_<area>(m)` per file (as small_gicp's bindings):
///   define_config      default_config, preset_config, preset_names, check_config
///   define_io          read_cloud, synthetic_scene
///   define_result      Result and Level, the views of a registration's report
///   define_register    register, register_correspondences
/// Every core error (pagor::Error) is raised as pagor.Error, a subclass of ValueError, with the
/// core's message.

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <utility>

namespace pagor::python {

namespace py = pybind11;

/// A registration's outcome: the report the CLI writes with --json (schema pagor.register/1, or
/// pagor.register-correspondences/1 for correspondences). Python's Result and Level read their
/// attributes from it, so they cannot disagree with to_json().
struct Result {
  nlohmann::json report;
};

void define_config(py::module_& m);
void define_io(py::module_& m);
void define_result(py::module_& m);
void define_register(py::module_& m);

}  // namespace pagor::python
