// SPDX-License-Identifier: MIT
// sim::ConfigError as swarmpath.ConfigError, a ValueError carrying the file, line and key.
#include "bindings.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::python {

void bind_errors(py::module_& m) {
  // the class lives as long as the module; the handle is never released at exit
  static py::handle error_type;
  const py::exception<sim::ConfigError> type(m, "ConfigError", PyExc_ValueError);
  type.doc() =
      "Bad input (a scenario, params or config file, or an argument): str() reads 'file:line: key: message', "
      "as the command line prints it. Attributes: file, line (0 when there is none), key ('' when none).";
  error_type = type.inc_ref();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const sim::ConfigError& e) {
      const py::object error = py::reinterpret_borrow<py::object>(error_type)(e.what());
      error.attr("file") = e.file();
      error.attr("line") = e.line();
      error.attr("key") = e.key();
      PyErr_SetObject(error_type.ptr(), error.ptr());
    }
  });
}

}  // namespace swarmpath::python
