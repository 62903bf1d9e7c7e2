// SPDX-License-Identifier: MIT
// The whole state of an evolution run between generations (optimiser state with its random
// generator, generation, evaluation count, per-generation log, best-so-far list, config hash)
// as JSON, written atomically after every generation so that --resume continues exactly.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/atomic_write.hpp"
#include "evolve/fitness.hpp"
#include "evolve/optim/optimizer.hpp"
#include "evolve/optim/state_reader.hpp"

namespace swarmpath::evolve {

/// One generation: a row of log.csv.
struct GenerationRecord {
  std::int64_t generation = 0;     ///< 0-based
  double best = 0.0;               ///< lowest candidate fitness (mean over the cases)
  double mean = 0.0;               ///< mean candidate fitness
  double std = 0.0;                ///< population standard deviation of the candidate fitness
  double best_so_far = 0.0;        ///< lowest candidate fitness up to this generation
  double best_success_rate = 0.0;  ///< success rate of this generation's best candidate
  std::int64_t evaluations = 0;    ///< candidates evaluated so far (all generations)
  double seconds = 0.0;            ///< wall time so far, resumes included (0 without wall time)
  // multi-objective runs only (best, mean, std and best_so_far stay 0 there)
  double hypervolume = 0.0;  ///< of the feasible front, against the config's reference point
  int front_size = 0;        ///< points of the feasible non-dominated front
  int feasible = 0;          ///< feasible candidates of this generation
  Vector front_min;          ///< per objective, the front's lowest value (empty: no front)
  // the tuned values (decoded, in gene order): the parameter trajectories of `swarmpath report`
  Vector tuned_best;                        ///< of the generation's best candidate (empty: none)
  Vector tuned_mean, tuned_min, tuned_max;  ///< over its valid candidates (empty: none valid)
  // [reevaluate] every_generation: this generation's best on the validation set
  int validation_runs = 0;               ///< 0: not evaluated
  double validation_fitness = 0.0;       ///< its mean fitness there
  double validation_success_rate = 0.0;  ///< its success rate there
  // [evaluation] capping: what it did this generation (evolve/capping.hpp's CappingTally)
  int capped_candidates = 0;      ///< candidates with a censored fitness
  std::int64_t capped_runs = 0;   ///< runs stopped at T_c for good
  std::int64_t reruns = 0;        ///< open runs run again in full
  std::int64_t ticks_capped = 0;  ///< sum of T_max - T_c over capped runs (the most they saved)
  std::int64_t ticks_rerun = 0;   ///< sum of T_c over reruns (their first try's cost)
};

/// A distinct candidate among the best so far, by its generation mean.
struct Elite {
  Vector x;                    ///< the optimiser's coordinates
  std::vector<double> values;  ///< its decoded tuned values (what makes candidates distinct)
  CandidateStats stats;        ///< over its generation's cases (the best, if it came back)
  std::int64_t generation = 0;
  int candidate = 0;  ///< index in its generation's batch; kDistributionMean for the optimiser's mean
};

/// Elite::candidate of a finalist that is the optimiser's distribution mean after generation
/// `generation`, the last ([reevaluate] mean_finalist): never simulated, so its stats are empty.
inline constexpr int kDistributionMean = -1;

/// Where a finalist came from, for its row and header: "generation 3, candidate 5" or
/// "the distribution mean after generation 4" (short: "gen 3 #5", "mean after gen 4").
std::string elite_origin(const Elite& e, bool short_form = false);

/// Everything a resume needs.
struct RunState {
  std::string config_hash;
  std::int64_t generation = 0;   ///< generations completed
  std::int64_t evaluations = 0;  ///< candidates evaluated
  std::int64_t runs = 0;         ///< simulations run (penalised candidates run none)
  double seconds = 0.0;          ///< recorded wall time (0 without wall time)
  nlohmann::json optimizer;      ///< Optimizer::state()
  std::vector<GenerationRecord> history;
  std::vector<Elite> elites;  ///< sorted: fitness, then generation, then candidate; multi-objective
                              ///< runs: the optimiser's population, in its order (front() is within)
};

nlohmann::ordered_json stats_json(const CandidateStats& s);
/// Reads stats_json's object strictly (StateError naming the field).
CandidateStats stats_from_state(const StateReader& r);

nlohmann::ordered_json checkpoint_json(const RunState& s);

/// Reads a checkpoint strictly: every field's type and range, and its agreement with the rest of the
/// checkpoint (the history counts the generations and evaluations, best_so_far is the lowest best);
/// throws StateError naming the field. check_resumed_state checks it against the config.
RunState checkpoint_from_json(const nlohmann::json& j);

/// Reads DIR/checkpoint.json; throws ConfigError naming the file (and the field) when it is
/// missing, not JSON or not a checkpoint that reads back.
RunState read_checkpoint(const std::string& path);

}  // namespace swarmpath::evolve
