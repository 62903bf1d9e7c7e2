// SPDX-License-Identifier: MIT
// The `swarmpath` command line. run_cli is what main() calls and what the CLI tests call.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "evolve/batch.hpp"

namespace swarmpath::app {

/// Exit codes: 0 success, 1 runtime failure, 2 bad input (command line or files).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

/// Runs `swarmpath args...` (args without the program name); writes results to `out`,
/// messages and progress to `err`; returns the exit code.
/// `evaluators` makes what table, evaluate and evolve run their simulations on (this process's
/// threads unless main() runs as rank 0 of an MPI job).
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
            const evolve::EvaluatorFactory& evaluators = evolve::thread_pool_factory());

}  // namespace swarmpath::app
