// SPDX-License-Identifier: MIT
// The master's own capacity: how many tasks per second rank 0 hands out and takes back when the
// tasks cost nothing (a null objective: the other ranks answer each task at once with empty
// Metrics, through the same messages a real run sends; rank 0 runs none itself). With tasks of d
// seconds each, rank 0 could keep about rate x d threads busy.
//   mpirun -np K build/release/bench/mpi_master [tasks per batch] [batches] [threads per rank]
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "evolve/batch.hpp"
#include "evolve/mpi/job.hpp"
#include "evolve/mpi/mpi_evaluator.hpp"
#include "evolve/stopwatch.hpp"

namespace {

using namespace swarmpath;

sim::Metrics null_task(const evolve::SimBatch&, std::size_t) { return sim::Metrics{}; }

}  // namespace

int main(int argc, char** argv) {
  const int per_batch = argc > 1 ? std::atoi(argv[1]) : 20000;
  const int batches = argc > 2 ? std::atoi(argv[2]) : 5;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 1;
  if (per_batch < 1 || batches < 1 || threads < 1) {
    std::cerr << "usage: mpirun -np K mpi_master [tasks per batch] [batches] [threads per rank]\n";
    return 2;
  }
  return mpi::run_job(
      argc, argv,
      [&](const evolve::EvaluatorFactory&) {
        const int ranks = mpi::rank_count();
        if (ranks < 2) {
          std::cerr << "mpi_master: start it with mpirun -np 2 or more\n";
          return 2;
        }
        mpi::MpiEvaluator master(ranks, threads, null_task, /*local_threads=*/0);
        evolve::SimBatch b;
        b.add_scenario(std::make_shared<const sim::Scenario>());
        b.add_params(sim::Params{});
        for (int k = 0; k < per_batch; ++k) b.tasks.push_back({0, 0, sim::Mode::kPathFormation, 0});
        const evolve::Stopwatch clock;
        for (int i = 0; i < batches; ++i) master.run(b);
        const double s = clock.seconds();
        const double n = static_cast<double>(per_batch) * batches;
        std::printf(
            "mpi_master: %d ranks (rank 0 hands out only) x %d threads: %.0f null tasks in %.2f s = %.0f "
            "tasks per second, %.1f us each\n",
            ranks, threads, n, s, n / s, 1e6 * s / n);
        std::printf(
            "  a master at this rate keeps busy about %.0f threads whose tasks last 1 s, %.0f whose last 0.1 "
            "s\n",
            n / s, 0.1 * n / s);
        return 0;
      },
      std::cerr, null_task);
}
