// SPDX-License-Identifier: MIT
// Runs the CLI in-process for tests: exit code, standard output and standard error.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
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

/// A scratch folder of this test process, named after `what`.
inline std::filesystem::path temp_dir(const std::string& what) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("swarmpath_" + what + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// The whole text of a file ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace swarmpath::app::cli_support
