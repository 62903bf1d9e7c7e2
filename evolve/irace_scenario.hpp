// SPDX-License-Identifier: MIT
// An irace tuning scenario (irace 3.x, López-Ibáñez et al.) written from an evolve config: the
// tuned parameters as irace's parameters.txt, the training settings as instances, a target runner
// that runs one simulation through `swarmpath irace run` and prints its fitness, the base params
// as irace's initial configuration, and scenario.txt with the config's simulation budget.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/evolve_config.hpp"

namespace swarmpath::evolve {

struct IraceScenarioOptions {
  std::string out_dir;                          ///< where the files go (created)
  std::string swarmpath;                        ///< absolute path of the CLI the target runner calls
  std::optional<std::int64_t> max_experiments;  ///< default: simulation_budget(c).total
  int parallel = 1;                             ///< target runners irace runs at once
  std::optional<std::uint64_t> seed;            ///< irace's seed (default: the config's master seed)
};

/// The manifest `swarmpath irace import` reads back (swarmpath-irace.json).
struct IraceManifest {
  std::string config;  ///< the evolve config, absolute
  std::string config_hash;
  std::int64_t max_experiments = 0;
  int parallel = 1;
  std::uint64_t seed = 0;
  std::vector<std::string> instances;  ///< instance lines, in instances.txt order
};

/// irace's parameter line of every tuned parameter, in gene order: `name "--name=" type (range)`
/// where the type is r or i (with ",log" for a log scale; integers and steps with whole-number
/// bounds are i), or c for bools (false, true) and choices (their names). Values between the grid
/// points of a `step` are rounded to the grid by the target runner (as the genome's decoding does).
std::vector<std::string> irace_parameter_lines(const Genome& g);

/// The instance lines: an absolute scenario file and `--robots N`, one per training setting.
/// Throws ConfigError when a path holds whitespace (irace splits instance lines at spaces).
std::vector<std::string> irace_instance_lines(const EvolveConfig& c);

/// Writes parameters.txt, instances.txt, configurations.txt (the base params), target-runner,
/// scenario.txt, run-irace (runs irace there, then export-elites.R), export-elites.R (irace's
/// final elites from irace.Rdata into elites.csv) and swarmpath-irace.json. Returns the manifest.
/// Throws ConfigError for configs irace cannot take (multi-objective, wall-time budget only).
IraceManifest write_irace_scenario(const EvolveConfig& c, const IraceScenarioOptions& o);

nlohmann::ordered_json manifest_json(const IraceManifest& m);

/// Reads swarmpath-irace.json from `dir`; ConfigError when it is missing or malformed.
IraceManifest read_irace_manifest(const std::string& dir);

}  // namespace swarmpath::evolve
