// SPDX-License-Identifier: MIT
// What the subcommands share: params and scenario loading, number formatting, a stopwatch.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/stopwatch.hpp"
#include "sim/controller.hpp"
#include "sim/metrics.hpp"
#include "sim/params.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::app {

/// An output file of a command: its path ("" when it was not asked for) and what writes it.
struct OutputFile {
  std::string path;
  std::function<void(std::ostream&)> write;
};

/// Writes each asked-for file with evolve::write_file_atomic, every one even when another fails (a
/// full disk loses one file, not the others), with an "error: cannot write FILE: ..." line on `err`
/// for each that failed. kExitOk, or kExitFailure when one failed.
int write_outputs(const std::vector<OutputFile>& files, std::ostream& err);

/// The params file, or the paper's defaults (SPEC §7) when `path` is empty.
sim::Params params_or_defaults(const std::string& path);

/// Parses --mode; throws ConfigError listing the choices.
sim::Mode mode_from_option(const std::string& text);

/// A LED colour from its SPEC §2.2 name (green, red, ...); throws ConfigError naming `option`.
sim::Led led_from_option(const std::string& option, const std::string& text);

/// A scenario with the command line's overrides (robots, ticks) applied and checked.
sim::Scenario scenario_with_overrides(const std::string& path, std::optional<std::int64_t> robots,
                                      std::optional<std::int64_t> ticks);

/// Adds the path-formation fields of `simulate --json` (success, ticks_to_form, path lengths...).
void add_path_json(nlohmann::ordered_json& j, const sim::Metrics& m);

/// Says on `err` which of `scenarios` were drawn from a benchmark's seed: measuring on them is
/// what a benchmark is for, screening or tuning on them is not (docs/generalisation.md).
void note_benchmark_arenas(const std::vector<sim::Scenario>& scenarios, std::ostream& err);

/// The A* (8-connected) length of a scenario [TU]; nullopt when there is no path or the arena is too
/// large for the A* grid (then `why` says so, when given).
std::optional<double> astar8_tu(const sim::Scenario& s, std::string* why = nullptr);

/// Every field of `simulate --json` that the run determines (all but the wall-clock and file ones):
/// scenario, mode, controller, robots, seed, ticks, state_hash, ..., the path, allocation and fault fields.
nlohmann::ordered_json simulation_json(const sim::Params& p, const sim::Scenario& s, sim::Mode mode,
                                       std::uint64_t seed, const sim::Metrics& m,
                                       const std::optional<double>& astar8);

/// Fixed-point text with `digits` decimals.
std::string fixed(double v, int digits);

/// True when standard error is a terminal (progress lines are shown only then).
bool stderr_is_terminal();

/// Wall-clock stopwatch for reporting (never used inside the simulator).
using evolve::Stopwatch;

}  // namespace swarmpath::app
