// SPDX-License-Identifier: MIT
// Nothing lost, nothing silently wrong: every write is checked to its end (files and standard
// output), a failed write exits 1 naming the file and leaves the previous file as it was, and no
// output may replace an input or another output of the same command.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <streambuf>
#include <sys/resource.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::app {
namespace {

namespace fs = std::filesystem;
using Result = cli_support::CliResult;
using cli_support::cli;

using cli_support::short_chain;
using cli_support::source;

fs::path scratch(const std::string& name) { return cli_support::test_scratch("output_test", name); }

std::string joined(const std::vector<std::string>& args) {
  std::string s;
  for (const std::string& a : args) s += (s.empty() ? "" : " ") + a;
  return s;
}

// a standard output on a full disk: every write fails
class FullBuffer : public std::streambuf {
 protected:
  int_type overflow(int_type) override { return traits_type::eof(); }

  std::streamsize xsputn(const char*, std::streamsize) override { return 0; }
};

Result cli_with_full_stdout(const std::vector<std::string>& args) {
  FullBuffer full;
  std::ostream out(&full);
  std::ostringstream err;
  const int code = run_cli(args, out, err);
  return {code, "", err.str()};
}

std::string tiny_evolve_config(const fs::path& dir) {
  const std::string text = "name = \"tiny\"\nparams = \"" + source("genomes/default.toml") +
                           "\"\nmode = \"pf\"\nseed = 7\n\n[tune]\nw_away = {}\n\n[evaluation]\n"
                           "scenarios = [\"" +
                           short_chain() +
                           "\"]\nrobots = [8]\nseeds = 1\nmax_ticks = 300\n\n[optimizer]\nname = "
                           "\"random\"\npopulation = 2\n\n[budget]\ngenerations = 1\n\n[reevaluate]\n"
                           "top_k = 1\nseeds = 1\n";
  cli_support::write_file(dir / "tiny.toml", text);
  return (dir / "tiny.toml").string();
}

TEST(WriteErrors, EveryCommandFailsWhenItsStandardOutputCannotBeWritten) {
  const fs::path dir = scratch("stdout");
  const std::vector<std::vector<std::string>> commands = {
      {"--help"},
      {"simulate", "--help"},
      {"simulate", "--scenario", short_chain(), "--robots", "4", "--ticks", "5"},
      {"simulate", "--scenario", short_chain(), "--robots", "4", "--ticks", "5", "--json"},
      {"astar", "--scenario", short_chain()},
      {"astar", "--scenario", short_chain(), "--json"},
      {"table", "--scenarios", short_chain(), "--robots", "4", "--seeds", "1", "--ticks", "5"},
      {"evaluate", "--params", source("genomes/default.toml"), "--scenarios", short_chain(), "--robots", "4",
       "--seeds", "1", "--ticks", "5"},
      {"export", "--format", "json"},
      {"arena", "families"},
      {"arena", "generate", "--family", "wall-gap", "--seed", "7"},
      {"ablate", "--list"},
      {"benchmark", "--help"},
      {"robustness", "--help"},
      {"verify", "--help"},
      {"report", "--help"},
      {"view", "--help"},
      {"evolve", "--config", tiny_evolve_config(dir), "--out", (dir / "run").string(), "--threads", "2"},
  };
  for (const auto& args : commands) {
    const Result r = cli_with_full_stdout(args);
    EXPECT_EQ(r.code, kExitFailure) << joined(args) << "\n" << r.err;
    EXPECT_NE(r.err.find("cannot write standard output"), std::string::npos) << joined(args) << "\n" << r.err;
  }
}

TEST(WriteErrors, AFullDeviceAsAnOutputFileExitsOneNamingIt) {
  const std::vector<std::vector<std::string>> commands = {
      {"simulate", "--scenario", short_chain(), "--robots", "4", "--ticks", "5", "--svg", "/dev/full"},
      {"simulate", "--scenario", short_chain(), "--robots", "4", "--ticks", "5", "--heatmap", "/dev/full"},
      {"astar", "--scenario", short_chain(), "--svg", "/dev/full"},
      {"table", "--scenarios", short_chain(), "--robots", "4", "--seeds", "1", "--ticks", "5", "--json",
       "/dev/full"},
      {"table", "--scenarios", short_chain(), "--robots", "4", "--seeds", "1", "--ticks", "5", "--csv",
       "/dev/full"},
      {"table", "--scenarios", short_chain(), "--robots", "4", "--seeds", "1", "--ticks", "5", "--md",
       "/dev/full"},
      {"evaluate", "--params", source("genomes/default.toml"), "--scenarios", short_chain(), "--robots", "4",
       "--seeds", "1", "--ticks", "5", "--json", "/dev/full"},
      {"export", "--format", "argos", "--out", "/dev/full"},
      {"simulate", "--scenario", short_chain(), "--robots", "4", "--ticks", "5", "--record", "/dev/full"},
      {"arena", "generate", "--family", "wall-gap", "--seed", "7", "--out", "/dev/full"},
      {"arena", "generate", "--family", "wall-gap", "--seed", "7", "--svg", "/dev/full"},
  };
  for (const auto& args : commands) {
    const Result r = cli(args);
    EXPECT_EQ(r.code, kExitFailure) << joined(args) << "\n" << r.err;
    EXPECT_NE(r.err.find("cannot write /dev/full"), std::string::npos) << joined(args) << "\n" << r.err;
  }
}

// RLIMIT_FSIZE makes every write past `bytes` fail with EFBIG, as a full disk would
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit r = saved_;
    r.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &r);
  }

  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_);
  }

  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*previous_)(int) = nullptr;
};

TEST(WriteErrors, AWriteThatRunsOutOfSpaceLeavesThePreviousFileIntact) {
  const fs::path dir = scratch("full");
  const fs::path out = dir / "params.json";
  cli_support::write_file(out, "the previous export\n");
  Result r;
  {
    const FileSizeLimit limit(512);  // the JSON export is several KB
    r = cli({"export", "--format", "json", "--out", out.string()});
  }
  EXPECT_EQ(r.code, kExitFailure) << r.err;
  EXPECT_NE(r.err.find("cannot write " + out.string()), std::string::npos) << r.err;
  EXPECT_EQ(cli_support::read_file(out), "the previous export\n");
  // and no temporary file is left beside it
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"params.json"});
}

TEST(ProtectedInputs, NoOutputMayReplaceAnInput) {
  const fs::path dir = scratch("inputs");
  const fs::path params = dir / "p.toml";
  cli_support::write_file(params, "v_max = 10\n");
  const fs::path scenario = dir / "s.toml";
  cli_support::write_file(scenario, cli_support::read_file(short_chain()));
  const auto expect_refused = [&](const std::vector<std::string>& args, const std::string& out_option,
                                  const std::string& in_option) {
    const Result r = cli(args);
    EXPECT_EQ(r.code, kExitBadInput) << args[0] << " " << out_option << "\n" << r.err;
    EXPECT_NE(r.err.find(out_option), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(in_option), std::string::npos) << r.err;
  };
  expect_refused({"export", "--params", params.string(), "--out", params.string()}, "--out", "--params");
  expect_refused({"simulate", "--scenario", scenario.string(), "--ticks", "5", "--svg", scenario.string()},
                 "--svg", "--scenario");
  expect_refused({"simulate", "--scenario", scenario.string(), "--params", params.string(), "--ticks", "5",
                  "--heatmap", params.string()},
                 "--heatmap", "--params");
  expect_refused({"astar", "--scenario", scenario.string(), "--svg", scenario.string()}, "--svg",
                 "--scenario");
  expect_refused(
      {"table", "--scenarios", scenario.string(), "--robots", "4", "--seeds", "1", "--md", scenario.string()},
      "--md", "--scenarios");
  expect_refused(
      {"evaluate", "--params", params.string(), "--scenarios", scenario.string(), "--json", params.string()},
      "--json", "--params");
  expect_refused({"verify", "--genome", params.string(), "--config", params.string(), "--against",
                  params.string(), "--json", params.string()},
                 "--json", "--genome");
  // the same file under another name: a hard link, a symbolic link, a path with ./ and ..
  fs::create_hard_link(params, dir / "hard.toml");
  fs::create_symlink(params, dir / "soft.toml");
  expect_refused({"export", "--params", params.string(), "--out", (dir / "hard.toml").string()}, "--out",
                 "--params");
  expect_refused({"export", "--params", params.string(), "--out", (dir / "soft.toml").string()}, "--out",
                 "--params");
  expect_refused({"export", "--params", params.string(), "--out",
                  (dir / "." / ".." / dir.filename() / "p.toml").string()},
                 "--out", "--params");
  EXPECT_EQ(cli_support::read_file(params), "v_max = 10\n");
  EXPECT_EQ(cli_support::read_file(scenario), cli_support::read_file(short_chain()));
}

TEST(ProtectedInputs, TwoOutputsOfOneCommandMayNotShareAFile) {
  const fs::path dir = scratch("outputs");
  const std::string f = (dir / "x.out").string();
  Result r = cli({"simulate", "--scenario", short_chain(), "--ticks", "5", "--svg", f, "--heatmap", f});
  EXPECT_EQ(r.code, kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("--heatmap"), std::string::npos) << r.err;
  r = cli({"table", "--scenarios", short_chain(), "--robots", "4", "--seeds", "1", "--json", f, "--csv", f});
  EXPECT_EQ(r.code, kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("--csv"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(f));
  // devices are not files: two outputs may both go to /dev/null
  r = cli({"table", "--scenarios", short_chain(), "--robots", "4", "--seeds", "1", "--ticks", "5", "--json",
           "/dev/null", "--csv", "/dev/null"});
  EXPECT_EQ(r.code, kExitOk) << r.err;
}

TEST(ProtectedInputs, AnOutputInAMissingFolderIsRefusedBeforeAnyRun) {
  const Result r = cli({"table", "--scenarios", short_chain(), "--robots", "4", "--seeds", "1", "--json",
                        "/no/such/folder/t.json"});
  EXPECT_EQ(r.code, kExitBadInput) << r.err;
  EXPECT_NE(r.err.find("--json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/no/such/folder"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("runs,"), std::string::npos) << r.err;  // refused before the grid ran
}

}  // namespace
}  // namespace swarmpath::app
