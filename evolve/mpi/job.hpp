// SPDX-License-Identifier: MIT
// swarmpath as an MPI job. Under mpirun or srun, rank 0 runs the command line (the optimiser, the
// table, every file) and hands each batch's simulations out to every rank, its own threads
// included, one task per free thread, the longest expected first; the other ranks only simulate
// what they are sent (they read no file: a batch carries its params and scenarios). Results come
// back into their task's slot, so every file is the one a single process writes.
// This header does not include <mpi.h>; only evolve/mpi/*.cpp do.
#pragma once

#include <functional>
#include <iosfwd>

#include "evolve/batch.hpp"

namespace swarmpath::mpi {

/// True when an MPI launcher started this process (Open MPI's mpirun, a PMI or PMIx launcher such
/// as srun --mpi=pmix, MPICH's hydra).
bool launched_by_mpi();

/// The number of ranks in the job (once run_job has started MPI).
int rank_count();

/// Runs task k of a batch on the rank it was sent to.
using TaskRunner = sim::Metrics (*)(const evolve::SimBatch& batch, std::size_t k);

/// What rank 0 runs: the command, with a factory of evaluators that use every rank.
using RankZeroMain = std::function<int(const evolve::EvaluatorFactory& evaluators)>;

/// Initialises MPI, checks that every rank computes what rank 0 computes, runs `main` on rank 0
/// while the other ranks serve its batches, then shuts every rank down. Returns this process's
/// exit code: `main`'s on rank 0, 0 on the others. Messages go to `err` (rank 0's alone, but for
/// the errors only a rank itself can see).
/// `runner` runs each task (a null one measures the master's own capacity).
int run_job(int& argc, char**& argv, const RankZeroMain& main, std::ostream& err,
            TaskRunner runner = evolve::run_task);

}  // namespace swarmpath::mpi
