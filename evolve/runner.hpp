// SPDX-License-Identifier: MIT
// The evolution loop: ask the optimiser for a generation, decode each candidate, score every
// (candidate x case) on a BatchEvaluator (OpenMP threads or MPI ranks; one result slot each, so
// the run is bit-identical at any thread and rank count), tell the means back, keep the best distinct
// candidates, checkpoint, call the callbacks; at the end re-evaluate the finalists on fresh seeds and pick
// the best by that.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "evolve/base_selection.hpp"
#include "evolve/batch.hpp"
#include "evolve/checkpoint.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/folder_lock.hpp"
#include "evolve/genome.hpp"
#include "evolve/objective.hpp"
#include "evolve/optim/optimizer.hpp"
#include "evolve/racing.hpp"

namespace swarmpath::evolve {

/// Called after each generation (after the checkpoint is written); returning true stops the run
/// (ensmallen-style callbacks).
using GenerationCallback = std::function<bool(const GenerationRecord& record, const RunState& state)>;

/// Builds the optimiser (make_optimizer unless a test puts a fake in).
using OptimizerFactory = std::function<std::unique_ptr<Optimizer>(const OptimizerSettings&, const Bounds&,
                                                                  const Vector& x0, std::uint64_t seed)>;

struct RunOptions {
  std::string out_dir;                  ///< where the files go; empty: write none
  int threads = 1;                      ///< OpenMP threads; the results do not depend on it
  BatchEvaluator* evaluator = nullptr;  ///< where the simulations run; null: a ThreadPool of `threads`
  std::optional<int> generations;       ///< replaces the config's budget by this many generations
  bool resume = false;                  ///< continue from out_dir/checkpoint.json
  bool force = false;                   ///< start afresh over an earlier run (its files are moved aside)
  bool wall_time = true;                ///< false: every recorded wall time is 0 (bit-identical files)
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
  CandidateStats arenas;       ///< on the validation arenas alone (runs == 0 without families)
  int dropped_after = 0;       ///< racing: blocks run before it was dropped (0: every case; see racing.hpp)
  double p_value = 1.0;        ///< racing: the paired test's p-value when dropped
};

struct RunResult {
  RunState state;
  std::vector<Finalist> finalists;  ///< in elite order
  std::size_t best = 0;             ///< index of the finalist with the lowest re-evaluated fitness
  Finalist base;                    ///< the base params on the same fresh cases
  BaseSelection selection;          ///< keep_base: the best finalist tested against the base params
  std::string stop_reason;
  double seconds = 0.0;                      ///< recorded wall time (0 without wall time)
  std::vector<EvalSetting> settings;         ///< the objective's settings
  std::vector<EvalCase> cases;               ///< the cases of generation 0 (later ones differ in seed only)
  std::vector<EvalCase> reevaluation_cases;  ///< the finalists' cases
  RaceSummary race;                          ///< the re-evaluation's simulations (racing or not)

  /// The pick (best.toml): the base params when keep_base kept them, else the best finalist.
  const sim::Params& pick() const { return selection.base_kept ? base.params : finalists.at(best).params; }
};

/// The budget in force: the config's, or `generations` generations when given.
Budget effective_budget(const EvolveConfig& c, const std::optional<int>& generations);

/// The state to continue from: read from `checkpoint` and checked against the config's hash
/// (a ConfigError names both hashes when another config wrote it).
RunState resumed_state(const EvolveConfig& c, const std::string& checkpoint);

/// options.out_dir/checkpoint.json
std::string checkpoint_path(const RunOptions& options);

/// Locks options.out_dir for the whole run (FolderLock; none without an out_dir); throws
/// sim::ConfigError naming the holder when another run writes there.
std::optional<FolderLock> lock_run_folder(const EvolveConfig& c, const RunOptions& options);

/// The state a run starts from: fresh (with the config's hash), or with options.resume the
/// checkpoint in options.out_dir (checked by resumed_state, its optimiser state handed to
/// `restore`, announced through options.note; `resumed` says so). A resume of a folder stopped
/// before its first checkpoint (stopped_before_first_checkpoint) starts fresh, with a note. With
/// an out_dir (locked by lock_run_folder), first checks that no run file is an input and prepares
/// the folder (prepare_run_folder: an earlier run there is refused unless options.resume or
/// options.force).
RunState starting_state(const EvolveConfig& c, const RunOptions& options,
                        const std::function<void(const nlohmann::json&)>& restore, bool& resumed);

/// The training cases of generation 0 (later generations differ in seed only); throws
/// std::invalid_argument when there are none.
std::vector<EvalCase> first_cases(const EvolveConfig& c, const std::vector<EvalSetting>& settings);

/// Every candidate decoded (repaired), in order.
std::vector<Decoded> decode_all(const Genome& g, const std::vector<Vector>& xs);

/// Books a generation's tuned values into `rec`: those of candidate `best` (when given) and the
/// mean, min and max over the candidates without a violation.
void book_tuned_values(GenerationRecord& rec, const Genome& g, const std::vector<Decoded>& decoded,
                       std::optional<std::size_t> best);

/// Ends generation rec.generation: counts it and its candidates into st, stamps rec with the
/// evaluation count and `seconds`, appends it, stores the optimiser's state, calls `write` (the
/// progress files; skipped when empty), then every callback. True when a callback asks to stop.
bool finish_generation(RunState& st, GenerationRecord rec, std::size_t candidates, double seconds,
                       nlohmann::json optimizer_state, const RunOptions& options,
                       const std::function<void(const RunState&)>& write);

/// Why a run stops before its next generation ("" to go on): "generations", "evaluations",
/// "wall time" (`seconds` is the wall time across resumes) or "optimizer done".
std::string budget_stop(const Budget& b, const RunState& st, double seconds, bool optimizer_done);

/// Each candidate's summary over its cases (scores as evaluate_batch returns them).
std::vector<CandidateStats> candidate_stats(const std::vector<RunScore>& scores, std::size_t candidates);

/// Candidate i's runs of a batch on `cases` that were on drawn arenas, in case order.
std::vector<RunScore> arena_runs(const std::vector<RunScore>& scores, std::size_t i,
                                 const std::vector<EvalSetting>& settings,
                                 const std::vector<EvalCase>& cases);

/// Candidate i's runs of a batch on `cases` (scores as evaluate_batch returns them), split into
/// those of training settings (first) and of held-out ones (second), each in case order.
std::pair<std::vector<RunScore>, std::vector<RunScore>> split_held_out(
    const std::vector<RunScore>& scores, std::size_t i, const std::vector<EvalSetting>& settings,
    const std::vector<EvalCase>& cases);

/// scores[i * cases.size() + j] is candidate i on case j (penalty() for candidates with a
/// violation, not simulated). Every simulation of the batch runs on `evaluator`; a failed one
/// throws once the batch is over.
std::vector<RunScore> evaluate_batch(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                     const std::vector<EvalCase>& cases, BatchEvaluator& evaluator,
                                     const BatchProgress& progress = {});

/// The same on a ThreadPool of `threads`.
std::vector<RunScore> evaluate_batch(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                     const std::vector<EvalCase>& cases, int threads,
                                     const BatchProgress& progress = {});

/// options.evaluator, or a ThreadPool of options.threads kept in `own`.
BatchEvaluator& evaluator_of(const RunOptions& options, std::unique_ptr<BatchEvaluator>& own);

/// Runs (or resumes) the evolution and writes its files into options.out_dir: log.csv,
/// fitness.svg and checkpoint.json after every generation; best.toml and run.json at the end.
RunResult run_evolution(const EvolveConfig& c, const CaseObjective& f, const RunOptions& options);

}  // namespace swarmpath::evolve
