// SPDX-License-Identifier: MIT
// The pybind11 module `swarmpath`: thin bindings over the simulator (sim::evaluate), the table
// and the evolve layer's configs, objective and batch runner. No logic of its own: every value
// is checked and computed by the same C++ the command line runs.
#pragma once

#include <pybind11/pybind11.h>
#include <string>

#include <nlohmann/json.hpp>

#include "sim/params.hpp"

namespace swarmpath::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_params(py::module_& m);
void bind_scenario(py::module_& m);
void bind_run(py::module_& m);
void bind_evolve(py::module_& m);

/// A parameter type's name: real, integer, bool or choice.
const char* type_name(sim::ParamType t);

/// A JSON value as the Python object json.loads makes of its text (NaN becomes None, as in the
/// command line's JSON).
py::object to_python(const nlohmann::ordered_json& j);

/// A dict as TOML text, one top-level key a line (nested dicts and lists inline), so that a
/// ConfigError's line is the key's position in the dict. Values: bool, int, float, str, dict,
/// list or tuple (and anything with __index__ or __float__); others raise ConfigError (`name`).
std::string toml_text(const py::dict& d, const std::string& name);

}  // namespace swarmpath::python
