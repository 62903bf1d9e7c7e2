// SPDX-License-Identifier: MIT
// Where simulations run. The runner, `table` and `evaluate` hand a batch of tasks (params,
// scenario, mode, seed) to a BatchEvaluator and get each task's Metrics back in task order
// (pagmo's batch evaluators are the model). ThreadPool runs them on this process's OpenMP
// threads; evolve/mpi runs them across the ranks of an MPI job. Nobody else knows which ran:
// each task's Metrics come from the pure sim::evaluate, so every backend gives the same bits.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sim/controller.hpp"
#include "sim/metrics.hpp"
#include "sim/params.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::evolve {

/// One simulation: sim::evaluate(params[params], *scenarios[scenario], mode, seed).
struct SimTask {
  std::uint32_t params = 0;    ///< index into SimBatch::params
  std::uint32_t scenario = 0;  ///< index into SimBatch::scenarios
  sim::Mode mode = sim::Mode::kPathFormation;
  std::uint64_t seed = 0;
};

/// A batch: the parameter sets and scenarios its tasks name, each stored once. Everything a
/// task needs travels with the batch (no file is read to run it), so a scenario made in memory,
/// such as a generated arena, runs anywhere.
struct SimBatch {
  std::vector<sim::Params> params;
  std::vector<std::shared_ptr<const sim::Scenario>> scenarios;
  std::vector<SimTask> tasks;

  /// The index of `s` in scenarios, added when new (the same object is stored once).
  std::uint32_t add_scenario(std::shared_ptr<const sim::Scenario> s);

  /// The index of a new parameter set.
  std::uint32_t add_params(const sim::Params& p);
};

/// Called from the thread that runs the batch: tasks finished of total.
using BatchProgress = std::function<void(std::size_t done, std::size_t total)>;

/// Runs batches of simulations.
class BatchEvaluator {
 public:
  virtual ~BatchEvaluator() = default;

  /// Every task's Metrics, in task order, whoever ran it. When tasks fail, the batch still
  /// finishes; then std::runtime_error names the first failed task (in task order).
  virtual std::vector<sim::Metrics> run(const SimBatch& batch, const BatchProgress& progress = {}) = 0;

  /// Where the tasks run, e.g. "2 threads" or "3 MPI ranks x 2 threads".
  virtual std::string describe() const = 0;

  /// What the batches so far took: tasks, tasks per second, how busy the workers were ("" when
  /// nothing ran).
  virtual std::string summary() const = 0;
};

/// This process's OpenMP threads, one task per thread at a time, longest expected first.
class ThreadPool final : public BatchEvaluator {
 public:
  explicit ThreadPool(int threads);

  std::vector<sim::Metrics> run(const SimBatch& batch, const BatchProgress& progress = {}) override;
  std::string describe() const override;
  std::string summary() const override;

 private:
  int threads_;
  std::size_t tasks_ = 0;
  double seconds_ = 0.0;       // wall time inside run()
  double busy_seconds_ = 0.0;  // summed over threads
};

/// Makes the evaluator a command runs its batches on, given its --threads.
using EvaluatorFactory = std::function<std::unique_ptr<BatchEvaluator>(int threads)>;

/// The factory of ThreadPool (what runs without MPI).
EvaluatorFactory thread_pool_factory();

/// What a task is expected to cost, in relative units: robots x T_max (a run that fails lasts to
/// T_max) times the mode's cost per robot-tick (task allocation ~3.4x path formation, measured
/// by sim_bench's whole-run benchmarks). Only an order: it never changes a result.
double expected_cost(const sim::Scenario& s, sim::Mode mode);

/// The order to hand tasks out in: the longest expected first (so that a long run does not
/// start last and hold up the batch), ties in task order.
std::vector<std::uint32_t> handout_order(const SimBatch& batch);

/// Runs task `k` of `batch` (what every backend calls).
sim::Metrics run_task(const SimBatch& batch, std::size_t k);

/// Throws std::runtime_error for the first non-empty error, naming the task (scenario, robots,
/// mode, seed).
void throw_first_error(const SimBatch& batch, const std::vector<std::string>& errors);

}  // namespace swarmpath::evolve
