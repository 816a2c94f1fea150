#pragma once
/// \file bindings.hpp
/// The parts of the private extension `pagor._pagor`, one `define_<area>(m)` per file (as
/// small_gicp's bindings); the package's pure-Python modules (pagor/__init__.py, results.py,
/// _inputs.py) are the API around them, and _pagor.pyi states their types:
///   define_config      default_config, preset_config, preset_names, check_config, dump_json
///   define_io          read_cloud, synthetic_scene
///   define_register    register_clouds, register_correspondences: plain dicts of numpy arrays
///                      and the report, which results.py turns into Result, Level, ...
///   define_sets        bench_pairs, pair_keys, tool_version, config_json, FileLock: the result
///                      lines of `pagor bench --out` for sets.py's run_pairs
/// Every core error (pagor::Error) is raised as pagor.Error, a subclass of ValueError, with the
/// core's message.

#include <pybind11/pybind11.h>

namespace pagor::python {

namespace py = pybind11;

void define_config(py::module_& m);
void define_io(py::module_& m);
void define_register(py::module_& m);
void define_sets(py::module_& m);

}  // namespace pagor::python
