// SPDX-License-Identifier: MIT
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#ifdef SWARMPATH_HAS_MPI
#include "evolve/mpi/job.hpp"
#endif

namespace {

// srun -n N without an MPI plugin starts N copies that each run the whole job into the same
// files: refuse ("" when this is not such a copy)
std::string separate_srun_copy() {
  const char* tasks = std::getenv("SLURM_STEP_NUM_TASKS");
  if (!tasks || std::atoi(tasks) < 2 || !std::getenv("SLURM_PROCID")) return "";
  return std::string("error: srun started ") + tasks + " tasks (this is task " + std::getenv("SLURM_PROCID") +
         ") that do not form an MPI job: each would run the whole command into the same files. " +
#ifdef SWARMPATH_HAS_MPI
         "Start them with 'srun --mpi=pmix' (see 'srun --mpi=list') or mpirun, or run one task with --threads"
#else
         "This build has no MPI backend: run one task with --threads, or build with Open MPI (docs/mpi.md)"
#endif
         "\n";
}

// the command, in this process or, under mpirun or srun, as rank 0 of the job (every rank runs
// simulations; the others return 0)
int run(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
#ifdef SWARMPATH_HAS_MPI
  const bool mpi = swarmpath::mpi::launched_by_mpi();
#else
  const bool mpi = false;
#endif
  if (const std::string copy = separate_srun_copy(); !mpi && !copy.empty()) {
    std::cerr << copy;
    return swarmpath::app::kExitBadInput;
  }
#ifdef SWARMPATH_HAS_MPI
  if (mpi) {
    return swarmpath::mpi::run_job(
        argc, argv,
        [&](const swarmpath::evolve::EvaluatorFactory& evaluators) {
          return swarmpath::app::run_cli(args, std::cout, std::cerr, evaluators);
        },
        std::cerr);
  }
#endif
  return swarmpath::app::run_cli(args, std::cout, std::cerr);
}

}  // namespace

int main(int argc, char** argv) {
  // past the file-size limit (ulimit -f) a write fails with EFBIG, named like a full disk, instead of
  // SIGXFSZ killing the process between a temporary file and its rename
  std::signal(SIGXFSZ, SIG_IGN);
  const int code = run(argc, argv);
  // run_cli flushed and checked standard output; what C's stdio may still hold is checked here
  if ((std::fflush(stdout) != 0 || std::ferror(stdout) != 0) && code == swarmpath::app::kExitOk) {
    std::cerr << "error: cannot write standard output\n";
    return swarmpath::app::kExitFailure;
  }
  return code;
}
