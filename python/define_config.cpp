// pagor.default_config, preset_config, preset_names, check_config: configurations as dicts.

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "json_objects.hpp"
#include "pagor/config.hpp"

namespace pagor::python {

void define_config(py::module_& m) {
  m.def(
      "default_config", [] { return config_to_python(default_config()); },
      "The project's default configuration as a dict: every parameter, with the keys of the JSON "
      "configuration (`pagor config --print-default`; docs/config.md lists them with units).");
  m.def(
      "preset_config",
      [](const std::string& name) { return config_to_python(preset_config(name)); },
      py::arg("name"),
      "A preset as a dict: 'default', 'paper' (the published configuration) or 'indoor' (a scan "
      "against a floor plan). An unknown name raises pagor.Error (a ValueError) listing the "
      "names.");
  m.def("preset_names", &preset_names, "The names preset_config() takes.");
  m.def(
      "check_config",
      [](const py::object& config) { return config_to_python(config_from_python(config)); },
      py::arg("config"),
      "Checks a configuration dict as register() would and returns it complete: absent keys filled "
      "from its 'preset' (else the default). An unknown key, a wrong type or a value out of range "
      "raises pagor.Error (a ValueError) naming the key path, e.g. 'config: graph.bogus: unknown "
      "key'.");
}

}  // namespace pagor::python
