// SPDX-License-Identifier: MIT
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#ifdef SWARMPATH_HAS_MPI
#include "evolve/mpi/job.hpp"
#endif

namespace {

// the command, in this process or, under mpirun or srun, as rank 0 of the job (every rank runs
// simulations; the others return 0)
int run(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
#ifdef SWARMPATH_HAS_MPI
  if (swarmpath::mpi::launched_by_mpi()) {
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
  const int code = run(argc, argv);
  // run_cli flushed and checked standard output; what C's stdio may still hold is checked here
  if ((std::fflush(stdout) != 0 || std::ferror(stdout) != 0) && code == swarmpath::app::kExitOk) {
    std::cerr << "error: cannot write standard output\n";
    return swarmpath::app::kExitFailure;
  }
  return code;
}
