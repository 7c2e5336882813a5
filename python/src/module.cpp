// talus._talus: the compiled half of the talus package (python/talus/ is the other).
#include "bindings.h"

PYBIND11_MODULE(_talus, m) {
  m.doc() = "Talus engine bindings; import the talus package instead.";
  m.attr("__version__") = TALUS_VERSION;
  talus::python::bind_errors(m);
  pybind11::class_<talus::Snapshot> snapshot = talus::python::bind_snapshot(m);
  talus::python::bind_analyses(snapshot);
  talus::python::bind_collapse(m, snapshot);
  talus::python::bind_stepped_run(m);
}
