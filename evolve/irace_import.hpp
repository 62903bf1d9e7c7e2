// SPDX-License-Identifier: MIT
// irace's answer read back: the final elites (elites.csv, written from irace.Rdata by the
// export-elites.R of an irace scenario) as params files with their provenance.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "evolve/evolve_config.hpp"
#include "evolve/genome.hpp"
#include "evolve/irace_scenario.hpp"

namespace swarmpath::evolve {

/// One row of elites.csv: an elite configuration of irace's last iteration.
struct IraceElite {
  int rank = 0;                                             ///< 1: irace's best
  std::string id;                                           ///< irace's configuration ID
  std::vector<std::pair<std::string, std::string>> values;  ///< parameter name -> value as irace wrote it
  double mean_cost = 0.0;                                   ///< over the instance runs irace gave it
  std::int64_t runs = 0;                                    ///< instance runs behind mean_cost
  std::int64_t experiments = 0;                             ///< target-runner calls of the whole irace run
  std::string irace_version;
  std::string irace_seed;
};

/// Reads elites.csv; ConfigError (file, line, column) when it is malformed.
std::vector<IraceElite> read_irace_elites(const std::string& path);

/// The elite's values as the genome's candidate (rounded to the grid, cross constraints repaired).
/// ConfigError naming `file` and the parameter for a tuned parameter the row lacks, a parameter
/// the genome does not tune, or a value that is not one of the parameter's.
Decoded irace_elite_candidate(const Genome& g, const IraceElite& e, const std::string& file);

/// A params file of the elite: write_params_toml under a header that says where it came from
/// (irace's configuration, its mean cost, the irace version and seed, the evolve config and its
/// hash, the scenario folder, the swarmpath build).
std::string irace_params_toml(const EvolveConfig& c, const IraceManifest& m, const IraceElite& e,
                              const Decoded& d, const std::string& dir);

}  // namespace swarmpath::evolve
