// SPDX-License-Identifier: MIT
#include "common.hpp"

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <unistd.h>

#include "cli.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/params_export.hpp"
#include "fault_options.hpp"
#include "sim/arenas/registry.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "sim/hash.hpp"

namespace swarmpath::app {

int write_outputs(const std::vector<OutputFile>& files, std::ostream& err) {
  int code = kExitOk;
  for (const OutputFile& f : files) {
    if (f.path.empty()) continue;
    try {
      evolve::write_file_atomic(f.path, f.write);
    } catch (const evolve::WriteError& e) {
      err << "error: " << e.what() << "\n";
      code = kExitFailure;
    }
  }
  return code;
}

sim::Params params_or_defaults(const std::string& path) {
  if (path.empty()) return sim::Params{};
  return sim::load_params(path);
}

sim::Mode mode_from_option(const std::string& text) {
  if (const auto m = sim::parse_mode(text)) return *m;
  std::string choices;
  for (const sim::Mode m : sim::kModes)
    choices += (choices.empty() ? "" : ", ") + std::string(sim::to_string(m));
  throw sim::ConfigError("--mode", 0, "", "unknown mode \"" + text + "\" (choices: " + choices + ")");
}

sim::Led led_from_option(const std::string& option, const std::string& text) {
  std::string choices;
  for (int k = 0; k < sim::kLedCount; ++k) {
    const auto led = static_cast<sim::Led>(k);
    if (sim::name(led) == text) return led;
    choices += (choices.empty() ? "" : ", ") + std::string(sim::name(led));
  }
  throw sim::ConfigError(option, 0, "", "unknown LED colour \"" + text + "\" (choices: " + choices + ")");
}

sim::Scenario scenario_with_overrides(const std::string& path, std::optional<std::int64_t> robots,
                                      std::optional<std::int64_t> ticks) {
  sim::Scenario s = sim::load_scenario(path);
  if (robots) s = sim::with_robots(s, *robots);
  if (ticks) s = sim::with_max_ticks(s, *ticks);
  return s;
}

namespace {

nlohmann::json tu_or_null(double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); }

nlohmann::json tick_or_null(std::int64_t t) { return t < 0 ? nlohmann::json(nullptr) : nlohmann::json(t); }

}  // namespace

void add_path_json(nlohmann::ordered_json& j, const sim::Metrics& m) {
  j["success"] = m.success;
  j["ticks_to_form"] = tick_or_null(m.ticks_to_form);
  j["path_length_tu"] = tu_or_null(m.path_length_tu);
  j["subgoal_path_length_tu"] = tu_or_null(m.subgoal_path_length_tu);
  j["opt1_path_length_tu"] = tu_or_null(m.opt1_path_length_tu);
  j["path_robots"] = m.path_robots;
  j["ticks_to_chain"] = tick_or_null(m.ticks_to_chain);
  j["ticks_to_opt1"] = tick_or_null(m.ticks_to_opt1);
  j["ticks_to_goal"] = tick_or_null(m.ticks_to_goal);
  j["subgoals_laid"] = m.chain.subgoals_laid;
  j["subgoals_laid_goalward"] = m.chain.subgoals_laid_goalward;
  j["forming_from_goal_side"] = m.chain.forming_from_goal_side;
  if (m.allocated >= 0 || m.ticks_to_allocate >= 0 || !std::isnan(m.resource_reduction_pct)) {
    j["allocated"] = m.allocated;
    j["resource_reduction_pct"] = tu_or_null(m.resource_reduction_pct);
    j["ticks_to_allocate"] = tick_or_null(m.ticks_to_allocate);
    j["recruited"] = m.recruited;  // rest_recruit: resting robots that closed the chain (in `allocated`)
  }
}

void note_benchmark_arenas(const std::vector<sim::Scenario>& scenarios, std::ostream& err) {
  std::string names;
  for (const sim::Scenario& s : scenarios) {
    if (s.origin && sim::arenas::is_benchmark_seed(s.origin->seed))
      names += (names.empty() ? "" : ", ") + s.name;
  }
  if (names.empty()) return;
  err << "note: " << names << " were drawn from benchmark seeds: report these results, but never choose a "
      << "controller, a rule or a parameter by them (docs/generalisation.md)\n";
}

std::optional<double> astar8_tu(const sim::Scenario& s, std::string* why) {
  try {
    const sim::AStarResult a = sim::astar(s, {sim::Connectivity::kEight});
    if (a.found) return sim::to_tu(a.length_m);
  } catch (const sim::ConfigError& e) {
    if (why != nullptr) *why = e.what();
  }
  return std::nullopt;
}

nlohmann::ordered_json simulation_json(const sim::Params& p, const sim::Scenario& s, sim::Mode mode,
                                       std::uint64_t seed, const sim::Metrics& m,
                                       const std::optional<double>& astar8) {
  nlohmann::ordered_json j;
  j["scenario"] = s.name;
  j["scenario_file"] = s.file;
  j["env_class"] = std::string(sim::to_string(s.env_class));
  j["mode"] = std::string(sim::to_string(mode));
  j["controller"] = evolve::controller_json(p);
  j["robots"] = m.robots;
  j["seed"] = seed;
  j["ticks"] = m.ticks;
  j["max_ticks"] = s.sim.max_ticks;
  j["state_hash"] = sim::to_hex(m.state_hash);
  j["distance_m"] = m.distance_m;
  j["mean_speed_cm_s"] = m.mean_speed_cm_s;
  j["astar8_tu"] = astar8 ? nlohmann::json(*astar8) : nlohmann::json(nullptr);
  const bool pf = mode == sim::Mode::kPathFormation || mode == sim::Mode::kTaskAllocation;
  if (pf) add_path_json(j, m);
  if (mode == sim::Mode::kTaskAllocation && m.allocated < 0) {  // no allocation happened: say so explicitly
    j["allocated"] = nullptr;
    j["resource_reduction_pct"] = nullptr;
    j["ticks_to_allocate"] = nullptr;
  }
  if (s.faults.any()) {
    j["faults"] = faults_json(s.faults);
    j["failures"] = m.failures;
    j["chain_failures"] = m.chain_failures;
  }
  j["table_unit_cm"] = 10;
  return j;
}

std::string fixed(double v, int digits) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(digits) << v;
  return o.str();
}

bool stderr_is_terminal() { return isatty(STDERR_FILENO) != 0; }

}  // namespace swarmpath::app
