// SPDX-License-Identifier: MIT
// Runs the CLI in-process for tests: exit code, standard output and standard error.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"

namespace swarmpath::app::cli_support {

struct CliResult {
  int code;
  std::string out;
  std::string err;
};

inline CliResult cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = run_cli(args, out, err);
  return {code, out.str(), err.str()};
}

}  // namespace swarmpath::app::cli_support
