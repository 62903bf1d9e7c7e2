// SPDX-License-Identifier: MIT
// The fault-model options that simulate, table and robustness share (--fail-fraction,
// --packet-loss, ...): each overrides its key of the scenarios' `[faults]` tables.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scenario.hpp"

namespace CLI {
class App;
}

namespace swarmpath::app {

/// What the command line sets; unset options keep the scenario file's values.
struct FaultOptions {
  std::optional<double> fail_fraction;
  std::vector<std::int64_t> fail_window;
  std::optional<std::string> fail_target;
  std::optional<double> camera_miss;
  std::optional<double> camera_false;
  std::optional<double> packet_loss;
  std::optional<double> wheel_noise;
  std::optional<double> position_noise;
  std::optional<double> heading_noise;
};

/// Registers the options on `app`; `sweep` leaves out --fail-fraction and --packet-loss (a command
/// that sweeps them has its own lists).
void add_fault_options(CLI::App& app, FaultOptions& o, bool sweep = false);

/// `base` with the options applied; throws ConfigError naming the option when a value is invalid.
sim::FaultModel apply_fault_options(const sim::FaultModel& base, const FaultOptions& o);

/// The model as JSON (every key of `[faults]`).
nlohmann::ordered_json faults_json(const sim::FaultModel& f);

/// The sources that are on, e.g. "fail 10 % (any, ticks 0-6000), packet loss 30 %".
std::string faults_text(const sim::FaultModel& f);

/// A scenario with the options applied to its fault model.
sim::Scenario with_fault_options(const sim::Scenario& s, const FaultOptions& o);

}  // namespace swarmpath::app
