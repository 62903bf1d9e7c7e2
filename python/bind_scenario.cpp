// SPDX-License-Identifier: MIT
// swarmpath.Scenario: an arena read and checked by the scenario parser (sim/scenario.hpp).
#include <pybind11/stl.h>

#include "app/common.hpp"
#include "bindings.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_writer.hpp"

namespace swarmpath::python {

namespace {

py::tuple pair(const sim::Vec2& v) { return py::make_tuple(v.x, v.y); }

}  // namespace

void bind_scenario(py::module_& m) {
  py::class_<sim::Scenario> c(
      m, "Scenario",
      "An arena (SPEC §3.3): walls, obstacles, nest and goal beacons, deployment region, "
      "environment class and simulation settings. Immutable: with_robots() and "
      "with_max_ticks() return copies.");
  c.def_static("load", &sim::load_scenario, py::arg("path"),
               "Loads a scenario file (TOML), e.g. configs/scenarios/paper/env4.toml. Raises ConfigError (a "
               "ValueError) naming the file, line and key, as the command line does.")
      .def_static(
          "parse",
          [](const std::string& text, const std::string& name) { return sim::parse_scenario(text, name); },
          py::arg("text"), py::arg("name") = "<string>",
          "Parses scenario-file text; `name` stands for the file in error messages.")
      .def_static(
          "from_dict",
          [](const py::dict& d) {
            const std::string name = "<dict>";
            return sim::parse_scenario(toml_text(d, name), name);
          },
          py::arg("values"),
          "A scenario from the dict a scenario file's TOML reads as, e.g. {'name': 'corridor', 'nest': [-2, "
          "0], "
          "'goal': [2, 0], 'arena': {'size': [6, 4]}, 'deployment': {'size': [1.5, 1.5], 'robots': 20}, "
          "'box': "
          "[{'center': [0, 1], 'size': [0.5, 2]}]}; checked as a file is (a ConfigError's line is the "
          "top-level "
          "key's position in the dict).")
      .def(
          "with_robots",
          [](const sim::Scenario& s, std::int64_t n) { return sim::with_robots(s, n, "robots"); },
          py::arg("robots"), "A copy with another robot count (checked against the deployment region).")
      .def(
          "with_max_ticks",
          [](const sim::Scenario& s, std::int64_t t) { return sim::with_max_ticks(s, t, "max_ticks"); },
          py::arg("max_ticks"), "A copy with another tick limit T_max.")
      .def(
          "astar8_tu", [](const sim::Scenario& s) { return app::astar8_tu(s); },
          "The A* (8-connected) length from nest to goal in table units (1 TU = 10 cm); None without a path.")
      .def_readonly("name", &sim::Scenario::name)
      .def_readonly("file", &sim::Scenario::file, "The file it came from ('<dict>', '<string>' otherwise).")
      .def_property_readonly(
          "env_class", [](const sim::Scenario& s) { return std::string(sim::to_string(s.env_class)); },
          "open, obstacle or complex (selects the delta of Eq. 3).")
      .def_readonly("robots", &sim::Scenario::robots, "The default robot count.")
      .def_property_readonly(
          "max_ticks", [](const sim::Scenario& s) { return s.sim.max_ticks; }, "T_max [ticks].")
      .def_property_readonly(
          "arena_size", [](const sim::Scenario& s) { return pair(s.arena_size); }, "(width, height) [m].")
      .def_property_readonly(
          "nest", [](const sim::Scenario& s) { return pair(s.nest); }, "The nest beacon (x, y) [m].")
      .def_property_readonly(
          "goal", [](const sim::Scenario& s) { return pair(s.goal); }, "The goal beacon (x, y) [m].")
      .def(
          "to_toml",
          [](const sim::Scenario& s, const std::string& header) {
            return sim::write_scenario_toml(s, header);
          },
          py::arg("header") = "",
          "The scenario file text; Scenario.parse reads it back to the same scenario.")
      .def(py::pickle(
          [](const sim::Scenario& s) { return py::make_tuple(sim::write_scenario_toml(s), s.file); },
          [](const py::tuple& t) {
            sim::Scenario s = sim::parse_scenario(t[0].cast<std::string>(), "<pickle>");
            s.file = t[1].cast<std::string>();
            return s;
          }))
      .def("__repr__", [](const sim::Scenario& s) {
        return "Scenario(" + s.name + ", " + std::string(sim::to_string(s.env_class)) + ", " +
               std::to_string(s.robots) + " robots, " + std::to_string(s.sim.max_ticks) + " ticks, file " +
               s.file + ")";
      });
}

}  // namespace swarmpath::python
