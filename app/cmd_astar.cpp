// SPDX-License-Identifier: MIT
// swarmpath astar: the A* baseline lengths of a scenario (SPEC §4.5).
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/path_collision.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "svg.hpp"

namespace swarmpath::app {

namespace {

struct AStarCommandOptions {
  std::string scenario;
  double resolution = 0.01;
  double inflation = 0.085;
  std::string svg;
  bool json = false;
};

int run_astar(const AStarCommandOptions& o, std::ostream& out, std::ostream&) {
  if (!(o.resolution >= 0.001 && o.resolution <= 1.0)) {
    throw sim::ConfigError("--resolution", 0, "", "must lie in [0.001, 1] m");
  }
  if (!(o.inflation >= 0.0 && o.inflation <= 2.0)) {
    throw sim::ConfigError("--inflation", 0, "", "must lie in [0, 2] m");
  }
  evolve::check_output_paths({{"--scenario", o.scenario}}, {{"--svg", o.svg}});
  const sim::Scenario s = sim::load_scenario(o.scenario);
  const sim::AStarResult a8 = sim::astar(s, {sim::Connectivity::kEight, o.resolution, o.inflation});
  const sim::AStarResult a4 = sim::astar(s, {sim::Connectivity::kFour, o.resolution, o.inflation});
  const double euclid = sim::to_tu(sim::dist(s.nest, s.goal));
  const auto length = [](const sim::AStarResult& r) -> nlohmann::json {
    if (r.found) return sim::to_tu(r.length_m);
    return nullptr;
  };
  if (!o.svg.empty()) {
    Picture pic;
    pic.scenario = &s;
    if (a4.found)
      pic.lines.push_back(
          {a4.path, "#ff9a00", 2.0, "A* 4-connected: " + fixed(sim::to_tu(a4.length_m), 1) + " TU", false});
    if (a8.found)
      pic.lines.push_back(
          {a8.path, "#e00000", 2.0, "A* 8-connected: " + fixed(sim::to_tu(a8.length_m), 1) + " TU", false});
    pic.caption.push_back("A* baseline (SPEC 4.5): " + fixed(o.resolution * 100, 1) + " cm grid, inflation " +
                          fixed(o.inflation * 100, 1) + " cm; straight line " + fixed(euclid, 1) + " TU");
    write_svg_file(o.svg, pic);
  }
  if (o.json) {
    nlohmann::ordered_json j;
    j["scenario"] = s.name;
    j["scenario_file"] = s.file;
    j["astar8_tu"] = length(a8);
    j["astar4_tu"] = length(a4);
    j["euclid_tu"] = euclid;
    j["resolution_m"] = o.resolution;
    j["inflation_m"] = o.inflation;
    j["table_unit_cm"] = 10;
    out << j.dump(2) << "\n";
    return kExitOk;
  }
  const auto text = [](const sim::AStarResult& r) {
    return r.found ? fixed(sim::to_tu(r.length_m), 2) + " TU" : std::string("no path");
  };
  out << s.name << ": A*-8 " << text(a8) << ", A*-4 " << text(a4) << ", straight line " << fixed(euclid, 2)
      << " TU (1 TU = 10 cm)\n";
  return kExitOk;
}

}  // namespace

Runner add_astar(CLI::App& app) {
  auto o = std::make_shared<AStarCommandOptions>();
  app.add_option("--scenario", o->scenario, "Scenario file (TOML)")->required();
  app.add_option("--resolution", o->resolution, "Grid cell side [m]")->capture_default_str();
  app.add_option("--inflation", o->inflation, "Cells within this distance of an obstacle are blocked [m]")
      ->capture_default_str();
  app.add_option("--svg", o->svg, "Write a picture with both A* paths");
  app.add_flag("--json", o->json, "Print one JSON object (astar8_tu, astar4_tu, ...)");
  return [o](std::ostream& out, std::ostream& err) { return run_astar(*o, out, err); };
}

}  // namespace swarmpath::app
