#pragma once
/// \file json_objects.hpp
/// JSON documents (the configuration, the report) as Python objects and back: dict, list, str,
/// int, float, bool and None. The configuration a user passes as a dict is read by the core's own
/// parser (parse_config), so the keys, types and ranges are checked exactly as for a JSON file.

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>

#include "pagor/config.hpp"

namespace pagor::python {

namespace py = pybind11;

/// A JSON value as the Python object json.loads would give.
py::object to_python(const nlohmann::json& value);

/// Deepest nesting from_python reads, as the core's JSON reader (a deeper document would only
/// exhaust the stack).
constexpr int kMaxNesting = 64;

/// A Python object as JSON. Raises ValueError naming `origin` and the key path (`config:
/// graph.thresholds[1]: nan is not a finite number`) for what JSON cannot hold: non-string keys,
/// strings and keys that are not valid UTF-8 (lone surrogates), non-finite floats, integers beyond
/// 64 bits, other types, nesting deeper than kMaxNesting. `path` and `depth` are the object's own,
/// for the recursion.
nlohmann::json from_python(const py::handle& object, const std::string& origin,
                           const std::string& path = {}, int depth = 0);

/// The configuration: None gives default_config(); a dict is parsed like a JSON document (absent
/// keys keep the values of its `preset`, else of the default). Raises ValueError with the core's
/// message for an unknown key, a wrong type or a value out of range; TypeError for a non-dict.
Config config_from_python(const py::handle& config);

/// A configuration as a dict (config_to_json's document).
py::dict config_to_python(const Config& config);

}  // namespace pagor::python
