// The Python module ochre._ochre, wrapped by the package ochre (tools/python/ochre/__init__.py;
// docs/python.md).
#include "ochre/version.h"
#include "tools/python/py_support.h"

PYBIND11_MODULE(_ochre, m) {
  m.doc() = "ochre: spectral path tracer with Mueller-matrix polarization (docs/python.md)";
  m.attr("__version__") = OCHRE_VERSION;
  ochre::python::register_errors(m);
  ochre::python::register_scene(m);
  ochre::python::register_material(m);
  ochre::python::register_colour(m);
  ochre::python::register_relight(m);
}
