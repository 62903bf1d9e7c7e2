// SPDX-License-Identifier: MIT
// swarmpath.Params: the controller parameters of SPEC §7, loaded, parsed and replaced through the
// params-file parser, so that Python sees the same checks and messages as the command line.
#include <pybind11/stl.h>
#include <sstream>

#include "bindings.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/params_export.hpp"
#include "sim/params.hpp"

namespace swarmpath::python {

namespace {

std::string toml_of(const sim::Params& p, const std::string& header) {
  std::ostringstream out;
  sim::write_params_toml(out, p, header);
  return out.str();
}

bool same(const sim::Params& a, const sim::Params& b) {
  for (const sim::ParamInfo& info : sim::param_table()) {
    if (sim::get_value(a, info) != sim::get_value(b, info)) return false;
  }
  return true;
}

std::string repr(const sim::Params& p) {
  const sim::Params d;
  std::string out = "Params(";
  bool first = true;
  for (const sim::ParamInfo& info : sim::param_table()) {
    if (sim::get_value(p, info) == sim::get_value(d, info)) continue;
    out += (first ? "" : ", ") + std::string(info.name) + "=" + sim::format_value(p, info);
    first = false;
  }
  return out + (first ? "<defaults>)" : ")");
}

py::list param_table() {
  py::list out;
  const sim::Params d;
  for (const sim::ParamInfo& info : sim::param_table()) {
    py::dict e;
    e["row"] = info.row;
    e["name"] = std::string(info.name);
    e["type"] = type_name(info.type);
    e["default"] = to_python(evolve::param_value_json(d, info));
    e["lo"] = info.lo;
    e["hi"] = info.hi;
    e["step"] = info.step;
    e["unit"] = std::string(info.unit);
    e["fixed"] = std::string(info.fixed);
    e["meaning"] = std::string(info.meaning);
    if (info.type == sim::ParamType::kChoice) {
      e["choices"] = py::make_tuple(std::string(info.choices[0]), std::string(info.choices[1]));
    }
    out.append(e);
  }
  return out;
}

}  // namespace

const char* type_name(sim::ParamType t) {
  switch (t) {
    case sim::ParamType::kReal:
      return "real";
    case sim::ParamType::kInteger:
      return "integer";
    case sim::ParamType::kBool:
      return "bool";
    case sim::ParamType::kChoice:
      return "choice";
  }
  return "real";
}

void bind_params(py::module_& m) {
  py::class_<sim::Params> c(
      m, "Params",
      "The controller parameters of SPEC §7 (rows 1-42) and the options beyond it, as a "
      "params file holds them. Immutable in use: replace() returns a new one. Units as in "
      "the params files: cm, ticks (0.1 s), degrees.");
  c.def(py::init<>(), "The defaults (genomes/default.toml's values).")
      .def_static(
          "defaults", [] { return sim::Params{}; }, "The defaults (genomes/default.toml's values).")
      .def_static(
          "load", &sim::load_params, py::arg("path"),
          "Loads a params file (TOML, SPEC §7 names). Raises ConfigError (a ValueError) naming the file, "
          "line and key for an unknown key, a wrong type, a value out of range or a broken cross "
          "constraint, exactly as `swarmpath simulate --params` does.")
      .def_static(
          "parse",
          [](const std::string& text, const std::string& name) { return sim::parse_params(text, name); },
          py::arg("text"), py::arg("name") = "<string>",
          "Parses params-file text; `name` stands for the file in error messages.")
      .def_static(
          "from_dict",
          [](const py::dict& values) {
            const std::string name = "<dict>";
            return sim::parse_params(toml_text(values, name), name);
          },
          py::arg("values"),
          "Params from {name: value} (unset names keep their defaults), checked as a params file is: a "
          "ConfigError's line is the key's position in the dict.")
      .def(
          "replace",
          [](const sim::Params& p, const py::kwargs& values) {
            const std::string name = "Params.replace";
            return sim::parse_params(toml_text(values, name), name, p);
          },
          "A copy with some values replaced, e.g. p.replace(v_max=25, T_explore0=1500, t_source='elapsed'): "
          "the same checks and messages as a params file (ConfigError naming 'Params.replace', the "
          "argument's position as the line, and the key).")
      .def(
          "to_dict", [](const sim::Params& p) { return to_python(evolve::params_values_json(p)); },
          "{name: value} for every parameter in SPEC §7 order (bools as bool, choices by name).")
      .def(
          "__getitem__",
          [](const sim::Params& p, const std::string& name) {
            const sim::ParamInfo* info = sim::find_param(name);
            if (info == nullptr) throw py::key_error(name);
            return to_python(evolve::param_value_json(p, *info));
          },
          py::arg("name"), "One parameter's value by its SPEC §7 name, e.g. p['T_explore0'].")
      .def(
          "to_toml", [](const sim::Params& p, const std::string& header) { return toml_of(p, header); },
          py::arg("header") = "", "The params file text (every parameter, commented), after `header`.")
      .def(
          "save",
          [](const sim::Params& p, const std::string& path, const std::string& header) {
            evolve::write_file_atomic(path, toml_of(p, header));
          },
          py::arg("path"), py::arg("header") = "",
          "Writes the params file (atomically); Params.load reads it back to the same values.")
      .def_static(
          "names",
          [] {
            std::vector<std::string> out;
            for (const sim::ParamInfo& info : sim::param_table()) out.emplace_back(info.name);
            return out;
          },
          "Every parameter name, in SPEC §7 order.")
      .def("__eq__", &same, py::arg("other"))
      .def("__repr__", &repr)
      .def(py::pickle([](const sim::Params& p) { return toml_of(p, ""); },
                      [](const std::string& text) { return sim::parse_params(text, "<pickle>"); }));
  c.attr("__hash__") = py::none();
  m.def(
      "param_table", &param_table,
      "SPEC §7's table: one dict per parameter (row, name, type, default, lo, hi, step, unit, fixed, meaning "
      "and, for choices, choices).");
}

}  // namespace swarmpath::python
