// _pagor.default_config, preset_config, preset_names, check_config: configurations as dicts;
// dump_json: a report as the pagor tool writes it.

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "json_objects.hpp"
#include "pagor/config.hpp"
#include "pagor/report.hpp"

namespace pagor::python {

void define_config(py::module_& m) {
  m.def(
      "default_config", [] { return config_to_python(default_config()); },
      "pagor.default_config (see there).");
  m.def(
      "preset_config",
      [](const std::string& name) { return config_to_python(preset_config(name)); },
      py::arg("name"), "pagor.preset_config (see there).");
  m.def("preset_names", &preset_names, "pagor.preset_names (see there).");
  m.def(
      "check_config",
      [](const py::object& config) { return config_to_python(config_from_python(config)); },
      py::arg("config"), "pagor.check_config (see there).");
  m.def(
      "dump_json",
      [](const py::object& document, int indent) {
        return dump_report(from_python(document, "report"), indent);
      },
      py::arg("document"), py::arg("indent"),
      "A JSON document (dict) as text the way the pagor tool writes its reports (report.hpp's "
      "dump_report: indent clamped to [-1, 16], -1 one line).");
}

}  // namespace pagor::python
