// SPDX-License-Identifier: MIT
// The command line: help everywhere, exit code 2 with a clear message for bad input, and the
// JSON / SVG outputs the issues ask for.
#include "app/cli.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/svg.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::app {
namespace {

using Result = cli_support::CliResult;
using cli_support::cli;

std::string env(int k) {
  return std::string(SWARMPATH_SOURCE_DIR) + "/configs/scenarios/paper/env" + std::to_string(k) + ".toml";
}

std::filesystem::path temp_file(const std::string& name, const std::string& text) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("swarmpath_cli_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

TEST(Cli, HelpForTheProgramAndEachCommand) {
  Result r = cli({"--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("simulate"), std::string::npos);
  EXPECT_NE(r.out.find("astar"), std::string::npos);
  r = cli({"simulate", "--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* opt : {"--scenario", "--robots", "--seed", "--ticks", "--svg", "--json", "--params"}) {
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  }
  r = cli({"astar", "--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--resolution"), std::string::npos);
}

TEST(Cli, BadCommandLinesExitWithTwo) {
  EXPECT_EQ(cli({}).code, 2);
  EXPECT_EQ(cli({"fly"}).code, 2);
  EXPECT_EQ(cli({"simulate"}).code, 2);  // --scenario is required
  const Result r = cli({"simulate", "--scenario", env(1), "--bogus"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r.err;
  EXPECT_EQ(cli({"simulate", "--scenario", env(1), "--robots", "ten"}).code, 2);
}

TEST(Cli, MissingOrBrokenScenarioFile) {
  Result r = cli({"simulate", "--scenario", "/no/such/file.toml"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/no/such/file.toml: cannot open file"), std::string::npos) << r.err;
  std::string text;
  {
    std::ifstream in(env(4));
    std::stringstream ss;
    ss << in.rdbuf();
    text = ss.str();
  }
  text.replace(text.find("radius = 0.5"), 12, "radius = -0.5");
  const auto bad = temp_file("env4_bad.toml", text);
  r = cli({"simulate", "--scenario", bad.string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("env4_bad.toml:33: cylinder[0].radius: obstacle radius must be > 0"),
            std::string::npos)
      << r.err;
}

TEST(Cli, AbsurdOverridesAreRejected) {
  Result r = cli({"simulate", "--scenario", env(1), "--robots", "1000000000"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("exceed the limit"), std::string::npos) << r.err;
  r = cli({"simulate", "--scenario", env(1), "--ticks", "1000000000"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--ticks"), std::string::npos) << r.err;
  r = cli({"simulate", "--scenario", env(1), "--robots", "400"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("cannot hold 400 robots"), std::string::npos) << r.err;
  r = cli({"simulate", "--scenario", env(1), "--mode", "teleport"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown mode"), std::string::npos) << r.err;
}

TEST(Cli, BadParamsFile) {
  const auto p = temp_file("bad_params.toml", "v_max = 10\nd_sub = 200\n");
  const Result r = cli({"simulate", "--scenario", env(1), "--params", p.string(), "--ticks", "10"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad_params.toml:2: d_sub: value 200 lies outside its range"), std::string::npos)
      << r.err;
}

TEST(Cli, SimulateJsonHasTheRunFields) {
  const Result r =
      cli({"simulate", "--scenario", env(2), "--robots", "20", "--seed", "9", "--ticks", "200", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["robots"], 20);
  EXPECT_EQ(j["ticks"], 200);
  EXPECT_EQ(j["seed"], 9);
  const std::string hash = j["state_hash"];
  EXPECT_EQ(hash.size(), 16u);
  EXPECT_EQ(hash.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NEAR(j["astar8_tu"].get<double>(), 112.7, 0.2);
  // the same command again: the same hash
  const auto j2 = nlohmann::json::parse(
      cli({"simulate", "--scenario", env(2), "--robots", "20", "--seed", "9", "--ticks", "200", "--json"})
          .out);
  EXPECT_EQ(j2["state_hash"], j["state_hash"]);
}

TEST(Cli, SimulateWritesAnSvgPicture) {
  const auto dir = temp_file("x", "").parent_path();
  const auto svg = dir / "env4.svg";
  const Result r =
      cli({"simulate", "--scenario", env(4), "--ticks", "50", "--svg", svg.string(), "--trails"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(svg);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  EXPECT_EQ(text.rfind("<svg", 0), 0u);
  EXPECT_NE(text.find("#e00000"), std::string::npos);  // the A* path in red
  EXPECT_NE(text.find("#00ff00"), std::string::npos);  // robots with green LEDs
  EXPECT_NE(text.find("</svg>"), std::string::npos);
}

TEST(Cli, SimulateWritesAHeatMapOfWhereTheRobotsWere) {
  const auto dir = temp_file("h", "").parent_path();
  const auto map = dir / "env1_heat.svg";
  const Result r = cli({"simulate", "--scenario", env(1), "--robots", "10", "--ticks", "40", "--heatmap",
                        map.string(), "--heatmap-led", "green", "--heatmap-cell", "50"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("heat map"), std::string::npos) << r.out;
  std::ifstream in(map);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  EXPECT_EQ(text.rfind("<svg", 0), 0u);
  EXPECT_NE(text.find("occupancy of green robots over 40 ticks, 50 cm cells"), std::string::npos);
  EXPECT_NE(text.find(heat_color(1.0)), std::string::npos);  // the busiest cell is drawn darkest
  EXPECT_NE(text.find("#e00000"), std::string::npos);        // with the A* path
  // bad colour or cell size: exit 2, naming the option
  const Result bad = cli({"simulate", "--scenario", env(1), "--ticks", "5", "--heatmap", map.string(),
                          "--heatmap-led", "greem"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--heatmap-led: unknown LED colour \"greem\""), std::string::npos) << bad.err;
  EXPECT_EQ(cli({"simulate", "--scenario", env(1), "--ticks", "5", "--heatmap", map.string(),
                 "--heatmap-cell", "0"})
                .code,
            2);
}

TEST(Svg, HeatLevelIsALogScaleOverTwoDecadesBelowTheBusiestCell) {
  EXPECT_DOUBLE_EQ(heat_level(8.0, 8.0), 1.0);
  EXPECT_DOUBLE_EQ(heat_level(0.8, 8.0), 0.5);
  EXPECT_DOUBLE_EQ(heat_level(0.08, 8.0), 0.0);
  EXPECT_DOUBLE_EQ(heat_level(0.001, 8.0), 0.0);
  EXPECT_EQ(heat_color(0.0), "#ffffb2");  // pale yellow
  EXPECT_EQ(heat_color(0.5), "#fd8d3c");  // orange
  EXPECT_EQ(heat_color(1.0), "#800026");  // dark red
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string short_chain() { return std::string(SWARMPATH_SOURCE_DIR) + "/tests/data/short_chain.toml"; }

TEST(CliTable, OutputIsIdenticalAtOneAndTwoThreads) {
  const auto dir = temp_file("y", "").parent_path();
  const auto one = dir / "t1.json";
  const auto two = dir / "t2.json";
  const std::vector<std::string> base = {"table", "--scenarios", short_chain(), "--robots", "8,12", "--seeds",
                                         "2",     "--mode",      "pf",          "--ticks",  "12000"};
  auto a = base;
  a.insert(a.end(), {"--threads", "1", "--json", one.string()});
  auto b = base;
  b.insert(b.end(), {"--threads", "2", "--json", two.string(), "--csv", (dir / "t2.csv").string()});
  const Result ra = cli(a);
  const Result rb = cli(b);
  ASSERT_EQ(ra.code, 0) << ra.err;
  ASSERT_EQ(rb.code, 0) << rb.err;
  EXPECT_EQ(slurp(one), slurp(two));
  EXPECT_EQ(ra.out, rb.out);  // the markdown table too
  const auto j = nlohmann::json::parse(slurp(one));
  ASSERT_EQ(j["runs"].size(), 4u);
  for (const auto& run : j["runs"]) {
    for (const char* key :
         {"scenario", "robots", "seed", "mode", "success", "ticks_to_form", "path_length_tu",
          "subgoal_path_length_tu", "opt1_path_length_tu", "astar8_tu", "path_robots", "subgoals_laid",
          "subgoals_laid_goalward", "forming_from_goal_side"}) {
      EXPECT_TRUE(run.contains(key)) << key;
    }
    // every robot of a complete path was laid as a subgoal once at least
    if (run["success"].get<bool>()) {
      EXPECT_GE(run["subgoals_laid"].get<int>(), run["path_robots"].get<int>());
    }
  }
  EXPECT_TRUE(j["summary"].contains("success_rate_pf"));
  EXPECT_TRUE(j["summary"].contains("pct_pf_shorter_than_astar"));
  EXPECT_EQ(j["cases"].size(), 2u);
  EXPECT_NE(ra.out.find("| Env |"), std::string::npos);
  // the CSV has a header and one line per run
  const std::string csv = slurp(dir / "t2.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
}

TEST(CliTable, BothModesArePairedAndSummarised) {  // the paper's whole table: table --mode both
  const auto dir = temp_file("y", "").parent_path();
  const auto out = dir / "both.json";
  const Result r = cli({"table", "--scenarios", short_chain(), "--robots", "16", "--seeds", "2", "--mode",
                        "both", "--ticks", "12000", "--threads", "2", "--json", out.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(out));
  ASSERT_EQ(j["runs"].size(), 4u);  // 2 seeds x 2 modes
  std::map<std::string, std::set<std::uint64_t>> seeds;
  double rr_sum = 0;
  int ta_runs = 0;
  for (const auto& run : j["runs"]) {
    seeds[run["mode"].get<std::string>()].insert(run["seed"].get<std::uint64_t>());
    // a path can complete before the founder broadcasts DONE (seed 2): the allocated robots still count
    if (run["mode"] == "ta") {
      EXPECT_TRUE(run.contains("allocated") && run["allocated"].is_number()) << run.dump();
    }
    if (run["mode"] == "ta" && run.contains("allocated") && run["allocated"].is_number() &&
        run["allocated"].get<int>() > 0) {
      rr_sum += 100.0 * (16 - run["allocated"].get<int>()) / 16.0;
      ++ta_runs;
    }
  }
  EXPECT_EQ(seeds["pf"], seeds["ta"]);  // the same seeds with and without task allocation
  ASSERT_GT(ta_runs, 0);
  for (const char* key :
       {"success_rate_pf", "success_rate_ta", "pct_pf_shorter_than_astar", "pct_ta_shorter_than_astar",
        "pct_ta_faster", "pct_ta_shorter_than_pf", "mean_resource_reduction_pct"}) {
    EXPECT_TRUE(j["summary"].contains(key)) << key;
  }
  EXPECT_NEAR(j["summary"]["mean_resource_reduction_pct"].get<double>(), rr_sum / ta_runs, 1e-9);
  EXPECT_NE(r.out.find("paper"), std::string::npos);  // the paper's numbers beside ours
}

TEST(CliTable, RejectsBadGrids) {
  EXPECT_EQ(cli({"table", "--scenarios", short_chain(), "--robots", "500"}).code, 2);  // does not fit
  EXPECT_EQ(cli({"table", "--scenarios", short_chain(), "--seeds", "0"}).code, 2);
  EXPECT_EQ(cli({"table", "--scenarios", "/no/such/dir"}).code, 2);
}

TEST(Cli, AstarJson) {
  const Result r = cli({"astar", "--scenario", env(5), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["astar8_tu"].get<double>(), 158.9, 0.2);
  EXPECT_NEAR(j["astar4_tu"].get<double>(), 185.6, 0.2);
  EXPECT_EQ(cli({"astar", "--scenario", env(5), "--resolution", "0"}).code, 2);
}

}  // namespace
}  // namespace swarmpath::app
