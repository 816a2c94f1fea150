// The private extension `pagor._pagor`: the core's calls on numpy arrays and dicts. The package
// `pagor` (pagor/__init__.py) is the API around it.

#include "bindings.hpp"
#include "pagor/errors.hpp"

PYBIND11_MODULE(_pagor, m) {
  namespace python = pagor::python;
  m.doc() =
      "The private extension of the package pagor: the core's calls on numpy arrays and dicts. "
      "Use the package (import pagor): it checks the arguments and wraps the results.";
  m.attr("__version__") = PAGOR_VERSION;
  pybind11::register_exception<pagor::Error>(m, "Error", PyExc_ValueError);
  python::define_config(m);
  python::define_io(m);
  python::define_register(m);
  python::define_sets(m);
}
