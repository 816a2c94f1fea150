// The Python module `pagor`: global point-cloud registration with low overlap (Pagor).

#include "bindings.hpp"
#include "pagor/errors.hpp"

PYBIND11_MODULE(pagor, m) {
  namespace python = pagor::python;
  m.doc() =
      "Pagor: global point-cloud registration with low overlap (semantic landmarks, a pyramid of "
      "consistency graphs, cascaded densest cliques, GNC-TLS poses, verification on the dense "
      "clouds).\n\n"
      "register(source, target, ...) registers two clouds, register_correspondences(p, q, ...) a "
      "matcher's correspondences; read_cloud(path) reads every format the pagor tool reads. "
      "Configurations are dicts with the keys of the JSON configuration (default_config(), "
      "preset_config(name)). Bad arguments raise ValueError (pagor.Error for the core's own "
      "checks) with a message naming what was wrong.";
  m.attr("__version__") = PAGOR_VERSION;
  pybind11::register_exception<pagor::Error>(m, "Error", PyExc_ValueError);
  python::define_config(m);
  python::define_io(m);
  python::define_result(m);
  python::define_register(m);
}
