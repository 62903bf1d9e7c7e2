// SPDX-License-Identifier: MIT
// The `swarmpath` command line. run_cli is what main() calls and what the CLI tests call.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace swarmpath::app {

/// Exit codes: 0 success, 1 runtime failure, 2 bad input (command line or files).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

/// Runs `swarmpath args...` (args without the program name); writes results to `out`,
/// messages and progress to `err`; returns the exit code.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace swarmpath::app
