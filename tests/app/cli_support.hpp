// SPDX-License-Identifier: MIT
// Runs the CLI in-process for tests: exit code, standard output and standard error.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

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

#ifdef SWARMPATH_SOURCE_DIR
/// A file of the source tree, e.g. source("tests/data/short_chain.toml").
inline std::string source(const std::string& rel) { return std::string(SWARMPATH_SOURCE_DIR) + "/" + rel; }

/// The small open arena of the tests (tests/data/short_chain.toml).
inline std::string short_chain() { return source("tests/data/short_chain.toml"); }
#endif

/// An empty folder for the running test alone: TMP/swarmpath_<what>_<pid>/<suite>.<test>/<name>.
inline std::filesystem::path test_scratch(const std::string& what, const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      temp_dir(what) / (std::string(info->test_suite_name()) + "." + info->name()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `text` to `p`, byte for byte.
inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

/// The whole text of a file ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace swarmpath::app::cli_support
