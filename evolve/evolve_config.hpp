// SPDX-License-Identifier: MIT
// An evolve config (configs/evolve/*.toml): the base params file, the tuned parameters and
// their bounds, the evaluation set, the mode, the fitness weights, the optimiser, the budget,
// the master seed and the final re-evaluation; for a multi-objective optimiser (nsga2) the
// objectives, the success-rate constraint and the hypervolume reference point instead of weights. Read
// strictly: unknown keys, wrong types and impossible values are ConfigErrors naming file:line:key.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/base_selection.hpp"
#include "evolve/fitness.hpp"
#include "evolve/genome.hpp"
#include "evolve/optim/optimizer.hpp"
#include "evolve/pareto_objectives.hpp"
#include "sim/arenas/registry.hpp"
#include "sim/controller.hpp"
#include "sim/params.hpp"

namespace swarmpath::evolve {

/// A scenario file named by a config.
struct ScenarioRef {
  std::string written;             ///< as the config writes it (what config_json shows)
  std::string path;                ///< resolved (see resolve_path)
  std::uint64_t content_hash = 0;  ///< FNV-1a of the file's bytes (part of the config hash)
};

/// Arenas drawn from a family ([[evaluation.family]]): every generation draws `arenas` fresh ones,
/// shared by all candidates of the generation and by all robot counts.
struct FamilyEntry {
  sim::arenas::ArenaSpec spec;  ///< family and parameters; its robots parameter is max(robots)
  int arenas = 1;               ///< fresh arenas per generation
  std::vector<int> robots;      ///< robot counts
  int seeds = 1;                ///< runs per arena and robot count
};

/// Which simulations score a candidate: every scenario x robot count x seed, and every family
/// entry's arenas of the generation x robot count x seed.
struct EvaluationSet {
  std::vector<ScenarioRef> scenarios;
  std::vector<int> robots;                ///< robot counts; empty: each scenario's own count
  int seeds = 2;                          ///< seeds per (scenario, robots) and candidate
  std::optional<std::int64_t> max_ticks;  ///< overrides every scenario's T_max
  bool fixed_seeds = false;               ///< true: every generation reuses generation 0's seeds (and arenas)
  std::vector<FamilyEntry> families;      ///< arena families (beside or instead of the scenarios)
  bool capping = false;                   ///< adaptive capping of the runs (evolve/capping.hpp)
  double capping_fraction = 0.5;          ///< capping: first try of every run to this fraction of T_max
};

/// When the run stops (the first limit reached; 0 = no limit; at least one is set).
struct Budget {
  int generations = 0;
  std::int64_t evaluations = 0;  ///< candidates evaluated (one fitness value each)
  double wall_seconds = 0.0;     ///< wall time across resumes (makes the run length machine-dependent)
};

/// The end of a run: the best few distinct candidates on fresh seeds (and held-out scenarios).
struct Reevaluation {
  int top_k = 3;                      ///< finalists, distinct by their decoded params
  int seeds = 4;                      ///< fresh seeds per (scenario, robots)
  std::vector<ScenarioRef> held_out;  ///< extra scenarios, reported, not used to choose
  int arenas = 4;                     ///< validation arenas per family entry (seeds training never uses)
  bool every_generation = false;      ///< evaluate each generation's best on the validation set (log.csv)
  bool race = false;                  ///< race the finalists block by block (evolve/racing.hpp)
  double race_level = 0.05;           ///< racing: drop a finalist when its paired t-test p < this
  int race_first_test = 2;            ///< racing: blocks run before the first test (also race_base's)
  /// Race the finalists against the base params (evolve/base_racing.hpp): block by block, a
  /// finalist worse than the base params by a one-sided paired t-test at race_base_level is
  /// dropped, and the simulations it would have run buy more blocks of fresh cases for the rest;
  /// with every finalist dropped the re-evaluation stops. The same simulation budget at most.
  bool race_base = false;
  double race_base_level = 0.2;  ///< race_base: drop a finalist when its test of being worse has p < this
  /// The base params compete with the finalists on the fresh cases: the pick is the base params
  /// unless the best finalist beats them by a one-sided paired t-test (evolve/base_selection.hpp).
  /// Single-objective runs only (a multi-objective run reports its whole front).
  bool keep_base = true;
  double keep_base_level = 0.05;  ///< the family-wise level of that test (split over the finalists)
  KeepBaseTest keep_base_test = KeepBaseTest::kPairedT;  ///< that test: paired t or signed-rank
  /// The last of the top_k finalists is CMA-ES's distribution mean after the last generation
  /// (Optimizer::recommended_x), never simulated during the run, instead of the top_k-th best
  /// candidate by generation mean. CMA-ES only; the same simulations.
  bool mean_finalist = false;
};

struct EvolveConfig {
  std::string file;            ///< the config file (as given)
  std::string name;            ///< run name: the `name` key or the file's stem
  std::string params_written;  ///< base params file as written; empty: the paper's defaults
  std::string params_file;     ///< the same, resolved
  sim::Mode mode = sim::Mode::kPathFormation;
  std::uint64_t seed = 1;  ///< master seed
  Genome genome;           ///< tuned parameters on top of the base params
  EvaluationSet evaluation;
  FitnessWeights fitness;
  OptimizerSettings optimizer;
  Budget budget;
  Reevaluation reevaluate;
  MultiObjectiveSettings multi;  ///< [objectives]: set for multi-objective optimisers (nsga2) only

  /// True when the optimiser is a multi-objective one (it minimises `multi`, not `fitness`).
  bool multi_objective() const { return !multi.objectives.empty(); }
};

/// Loads and checks an evolve config (scenario and params files included). Relative paths in
/// it are resolved against the config file's folder first, then the working directory.
EvolveConfig load_evolve_config(const std::string& path);

/// The same from text; `name` stands for the file, `base_dir` for its folder.
EvolveConfig parse_evolve_config(std::string_view text, const std::string& name, const std::string& base_dir);

/// The config as JSON, every value explicit (defaults filled in, base params listed in full).
nlohmann::ordered_json config_json(const EvolveConfig& c);

/// FNV-1a of config_json without the budget (a resume may extend the budget), as 16 hex digits.
/// A checkpoint remembers it; resuming under another hash is refused.
std::string config_hash(const EvolveConfig& c);

/// `path` if absolute; else `base_dir/path` when that exists, else `path` itself when that
/// exists (relative to the working directory), else nullopt.
std::optional<std::string> resolve_path(const std::string& path, const std::string& base_dir);

}  // namespace swarmpath::evolve
