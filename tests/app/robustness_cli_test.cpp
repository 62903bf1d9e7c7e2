// SPDX-License-Identifier: MIT
// The fault options of simulate and table, and `swarmpath robustness`: the sweep's tables, JSON
// and SVG, and exit code 2 with the option's name for bad input.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/app/cli_support.hpp"

namespace swarmpath::app {
namespace {

using cli_support::cli;

std::string source(const std::string& relative) { return std::string(SWARMPATH_SOURCE_DIR) + "/" + relative; }

std::filesystem::path temp_dir() {
  const auto dir =
      std::filesystem::temp_directory_path() / ("swarmpath_robustness_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

std::string read(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(FaultCli, SimulateReportsTheFaultsAndTheFailures) {
  const auto r = cli({"simulate", "--scenario", source("tests/data/short_chain.toml"), "--mode", "pf",
                      "--seed", "1", "--fail-fraction", "0.1", "--fail-window", "0,0", "--fail-target",
                      "chain", "--camera-miss", "0.01", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["faults"]["fail_fraction"], 0.1);
  EXPECT_EQ(j["faults"]["fail_target"], "chain");
  EXPECT_EQ(j["faults"]["camera_miss"], 0.01);
  EXPECT_EQ(j["failures"], 2);
  EXPECT_EQ(j["chain_failures"], 2);
  // without faults the JSON has no such keys
  const auto plain = nlohmann::json::parse(
      cli({"simulate", "--scenario", source("tests/data/short_chain.toml"), "--mode", "pf", "--json"}).out);
  EXPECT_FALSE(plain.contains("faults"));
}

TEST(FaultCli, BadFaultOptionsExitWithTwoNamingTheOption) {
  const std::string s = source("tests/data/short_chain.toml");
  for (const auto& [option, value] :
       std::vector<std::pair<std::string, std::string>>{{"--packet-loss", "1.5"},
                                                        {"--fail-fraction", "-0.1"},
                                                        {"--camera-miss", "2"},
                                                        {"--fail-target", "everyone"},
                                                        {"--wheel-noise", "3"},
                                                        {"--fail-window", "10,5"}}) {
    const auto r = cli({"simulate", "--scenario", s, "--mode", "pf", option, value});
    EXPECT_EQ(r.code, 2) << option;
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
  }
  // ... and a bad [faults] table names its file, line and key
  const auto bad = temp_dir() / "bad_faults.toml";
  std::ofstream(bad) << read(s) << "\n[faults]\npacket_loss = 3\n";
  const auto r = cli({"table", "--scenarios", bad.string(), "--robots", "20", "--seeds", "1"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad_faults.toml:20: faults.packet_loss"), std::string::npos) << r.err;
  EXPECT_EQ(cli({"robustness", "--scenarios", s, "--fail-fractions", "0.1,0"}).code, 2);
  EXPECT_EQ(cli({"robustness", "--scenarios", s, "--packet-loss", "0,1.5"}).code, 2);
}

TEST(FaultCli, RobustnessSweepsFailuresAndPacketLoss) {
  const auto dir = temp_dir();
  const auto r = cli({"robustness",
                      "--scenarios",
                      source("tests/data/short_chain.toml"),
                      "--robots",
                      "20",
                      "--seeds",
                      "2",
                      "--fail-fractions",
                      "0,0.2",
                      "--fail-window",
                      "0,600",
                      "--packet-loss",
                      "0,1",
                      "--ticks",
                      "3000",
                      "--threads",
                      "2",
                      "--json",
                      (dir / "r.json").string(),
                      "--svg",
                      (dir / "r.svg").string(),
                      "--md",
                      (dir / "r.md").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("### Success (% of runs)"), std::string::npos);
  // the default tells sightings in path formation (share_sighting): a packet loss is a condition there too
  EXPECT_NE(r.out.find("| pf | 100 % |"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("any (no radio)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| ta | 100 % |"), std::string::npos);
  EXPECT_EQ(r.out.find("10 % of the robots failing"), std::string::npos);  // no 10 % column: no target line
  EXPECT_EQ(read(dir / "r.md"), r.out);
  const auto j = nlohmann::json::parse(read(dir / "r.json"));
  // both modes run at each failure fraction and packet loss
  EXPECT_EQ(j["runs"].size(), 2u * 2u * 2u + 2u * 2u * 2u);
  ASSERT_EQ(j["cells"].size(), 4u + 4u);
  EXPECT_EQ(j["path_formation_uses_radio"], true);
  int failed_robots = 0;
  for (const auto& run : j["runs"]) {
    if (run["fail_fraction"] == 0.0) {
      EXPECT_EQ(run["failures"], 0);
    }
    if (run["fail_fraction"] == 0.2) failed_robots += run["failures"].get<int>();
    // nothing heard: no robot allocated but the founders themselves, and no path
    if (run["mode"] == "ta" && run["packet_loss"] == 1.0) {
      EXPECT_FALSE(run["success"].get<bool>());
    }
  }
  EXPECT_EQ(failed_robots, 8 * 4);  // 4 robots in each of the eight runs, all within the first 600 ticks
  for (const auto& c : j["cells"]) EXPECT_TRUE(c["packet_loss"].is_number());
  const std::string svg = read(dir / "r.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("with task allocation, packet loss 100 %"), std::string::npos);
  EXPECT_NE(svg.find("robots failing (%)"), std::string::npos);
}

TEST(FaultCli, RobustnessWritesEveryOutputItCanAndNamesTheOneItCannot) {
  const auto dir = temp_dir() / "full";
  std::filesystem::create_directories(dir);
  const auto r = cli({"robustness",
                      "--scenarios",
                      source("tests/data/short_chain.toml"),
                      "--robots",
                      "4",
                      "--seeds",
                      "1",
                      "--fail-fractions",
                      "0",
                      "--packet-loss",
                      "0",
                      "--ticks",
                      "5",
                      "--threads",
                      "1",
                      "--md",
                      (dir / "r.md").string(),
                      "--json",
                      "/dev/full",
                      "--svg",
                      (dir / "r.svg").string()});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("cannot write /dev/full"), std::string::npos) << r.err;
  // the outputs before and after the one that failed are all there
  EXPECT_EQ(read(dir / "r.md"), r.out);
  EXPECT_EQ(read(dir / "r.svg").rfind("<svg", 0), 0u);
}

TEST(FaultCli, RobustnessRunsABenchmarksArenasBesideTheScenariosAndReportsEachGroup) {
  const auto dir = temp_dir();
  const auto config = dir / "tiny_benchmark.toml";
  std::ofstream(config) << "name = \"tiny\"\nversion = 1\ngenerator_version = 1\nrobots = [8]\nseeds = 1\n"
                           "max_ticks = 300\n\n[[family]]\nfamily = \"open\"\nseeds = [1000001, 1000002]\n"
                           "params = { width = 10, height = 8, distance_min = 3, distance_max = 4 }\n";
  // path formation without share_sighting uses no radio: its runs stand for every packet loss
  const auto params = dir / "no_telling.toml";
  std::ofstream(params) << "share_sighting = 0\n";
  const auto r = cli({"robustness",
                      "--params",
                      params.string(),
                      "--scenarios",
                      source("tests/data/short_chain.toml"),
                      "--benchmark",
                      config.string(),
                      "--robots",
                      "8",
                      "--seeds",
                      "1",
                      "--mode",
                      "pf",
                      "--fail-fractions",
                      "0,0.5",
                      "--fail-window",
                      "0,0",
                      "--packet-loss",
                      "0",
                      "--ticks",
                      "200",
                      "--threads",
                      "2",
                      "--json",
                      (dir / "b.json").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("### Success per arena group"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| data | pf | any (no radio) |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| tiny | pf | any (no radio) |"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(read(dir / "b.json"));
  EXPECT_EQ(j["groups"], nlohmann::json({"data", "tiny"}));
  EXPECT_EQ(j["scenarios"].size(), 3u);  // the scenario file and the benchmark's two arenas
  EXPECT_EQ(j["runs"].size(), 3u * 2u);  // ... at each failure fraction
  ASSERT_EQ(j["group_cells"].size(), 2u * 2u);
  for (const auto& c : j["group_cells"]) {
    EXPECT_EQ(c["runs"], c["scenario"] == "tiny" ? 2 : 1);
    EXPECT_EQ(c["failures"], c["fail_fraction"] == 0.5 ? 4.0 : 0.0);  // half of 8, all at tick 0
  }
  // a benchmark file that is not there is an input error
  EXPECT_EQ(cli({"robustness", "--benchmark", (dir / "missing.toml").string()}).code, 2);
}

}  // namespace
}  // namespace swarmpath::app
