// SPDX-License-Identifier: MIT
// The evolution loop: ask the optimiser for a generation, decode each candidate, score every
// (candidate x case) in parallel with OpenMP (one result slot each, so the run is bit-identical
// at any thread count), tell the means back, keep the best distinct candidates, checkpoint, call
// the callbacks; at the end re-evaluate the finalists on fresh seeds and pick the best by that.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "evolve/checkpoint.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/genome.hpp"
#include "evolve/objective.hpp"
#include "evolve/optim/optimizer.hpp"

namespace swarmpath::evolve {

/// Called after each generation (after the checkpoint is written); returning true stops the run
/// (ensmallen-style callbacks).
using GenerationCallback = std::function<bool(const GenerationRecord& record, const RunState& state)>;

/// Called from the calling thread while a batch runs: runs finished of total.
using BatchProgress = std::function<void(std::size_t done, std::size_t total)>;

/// Builds the optimiser (make_optimizer unless a test puts a fake in).
using OptimizerFactory = std::function<std::unique_ptr<Optimizer>(const OptimizerSettings&, const Bounds&,
                                                                  const Vector& x0, std::uint64_t seed)>;

struct RunOptions {
  std::string out_dir;             ///< where the files go; empty: write none
  int threads = 1;                 ///< OpenMP threads; the results do not depend on it
  std::optional<int> generations;  ///< replaces the config's budget by this many generations
  bool resume = false;             ///< continue from out_dir/checkpoint.json
  bool wall_time = true;           ///< false: every recorded wall time is 0 (bit-identical files)
  std::vector<GenerationCallback> callbacks;
  BatchProgress progress;                        ///< runs of the batch in flight
  std::function<void(const std::string&)> note;  ///< one-line messages (resume, re-evaluation)
  OptimizerFactory make_optimizer;               ///< empty: evolve::make_optimizer
};

/// A finalist after re-evaluation.
struct Finalist {
  Elite elite;                 ///< as it was found (generation mean)
  sim::Params params;          ///< decoded (repaired)
  CandidateStats reevaluated;  ///< on fresh seeds of the training settings: what picks the best
  CandidateStats held_out;     ///< on the held-out settings (runs == 0 when there are none)
};

struct RunResult {
  RunState state;
  std::vector<Finalist> finalists;  ///< in elite order
  std::size_t best = 0;             ///< index of the finalist with the lowest re-evaluated fitness
  Finalist base;                    ///< the base params on the same fresh cases, for reference only
  std::string stop_reason;
  double seconds = 0.0;                      ///< recorded wall time (0 without wall time)
  std::vector<EvalSetting> settings;         ///< the objective's settings
  std::vector<EvalCase> cases;               ///< the cases of generation 0 (later ones differ in seed only)
  std::vector<EvalCase> reevaluation_cases;  ///< the finalists' cases
};

/// The budget in force: the config's, or `generations` generations when given.
Budget effective_budget(const EvolveConfig& c, const std::optional<int>& generations);

/// scores[i * cases.size() + j] is candidate i on case j (penalty() for candidates with a
/// violation). Parallel over all (candidate, case) pairs; exceptions are rethrown afterwards.
std::vector<RunScore> evaluate_batch(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                     const std::vector<EvalCase>& cases, int threads,
                                     const BatchProgress& progress = {});

/// Runs (or resumes) the evolution and writes its files into options.out_dir: log.csv,
/// fitness.svg and checkpoint.json after every generation; best.toml and run.json at the end.
RunResult run_evolution(const EvolveConfig& c, const CaseObjective& f, const RunOptions& options);

}  // namespace swarmpath::evolve
