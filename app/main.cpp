// SPDX-License-Identifier: MIT
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "app/cli.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const int code = swarmpath::app::run_cli(args, std::cout, std::cerr);
  // run_cli flushed and checked standard output; what C's stdio may still hold is checked here
  if ((std::fflush(stdout) != 0 || std::ferror(stdout) != 0) && code == swarmpath::app::kExitOk) {
    std::cerr << "error: cannot write standard output\n";
    return swarmpath::app::kExitFailure;
  }
  return code;
}
