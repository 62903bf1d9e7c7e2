// SPDX-License-Identifier: MIT
// Rank 0's BatchEvaluator: it sends each batch to every other rank, then hands tasks out one per
// free thread, anywhere, the longest expected first, while its own threads take tasks from the
// same list; every result lands in its task's slot.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "evolve/batch.hpp"
#include "evolve/mpi/job.hpp"

namespace swarmpath::mpi {

class MpiEvaluator final : public evolve::BatchEvaluator {
 public:
  /// `ranks` ranks in the job (this is rank 0), `threads` threads on each of the others and
  /// `local_threads` here; `runner` runs a task (evolve::run_task, or a null task when
  /// measuring the master itself).
  MpiEvaluator(int ranks, int threads, TaskRunner runner, int local_threads);

  std::vector<sim::Metrics> run(const evolve::SimBatch& batch,
                                const evolve::BatchProgress& progress = {}) override;
  std::string describe() const override;
  std::string summary() const override;

 private:
  int ranks_;
  int threads_;
  TaskRunner runner_;
  int local_threads_;
  std::uint64_t batches_ = 0;     // batches sent so far (their ids are 1, 2, ...)
  std::size_t tasks_ = 0;         // tasks run so far
  double seconds_ = 0.0;          // wall time inside run()
  std::vector<double> busy_;      // per rank: seconds its threads spent simulating
  std::vector<std::size_t> ran_;  // per rank: tasks it ran
};

}  // namespace swarmpath::mpi
