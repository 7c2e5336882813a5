// Engine exceptions as Python ones. A scenario error is a ValueError whose text is the engine's
// own `FILE:LINE: KEY: message` lines, exactly as `talus run` prints them; a blow-up is a
// RuntimeError that also carries the step, time, particles and quantity it names.
#include <exception>

#include <pybind11/stl.h>

#include "bindings.h"
#include "talus/io/input_error.h"
#include "talus/scenario/stepped_run.h"

namespace talus::python {

void bind_errors(py::module_& m) {
  static py::exception<io::InputError> scenario_error(m, "ScenarioError", PyExc_ValueError);
  static py::exception<BlowUpError> blow_up_error(m, "BlowUpError", PyExc_RuntimeError);
  scenario_error.attr("__module__") = "talus";  // where users import them from
  blow_up_error.attr("__module__") = "talus";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const io::InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(scenario_error)(e.what());
      error.attr("messages") = py::cast(e.messages());
      PyErr_SetObject(scenario_error.ptr(), error.ptr());
    } catch (const BlowUpError& e) {
      const BlowUp& b = e.blow_up();
      py::object error = py::reinterpret_borrow<py::object>(blow_up_error)(e.what());
      error.attr("step") = b.step;
      error.attr("time") = b.time;
      error.attr("quantity") = b.quantity;
      error.attr("particles") = py::cast(b.particles);
      PyErr_SetObject(blow_up_error.ptr(), error.ptr());
    }
  });
}

}  // namespace talus::python
