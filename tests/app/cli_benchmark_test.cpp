// SPDX-License-Identifier: MIT
// The generalisation benchmark: its file is read strictly (arena seeds only from the benchmarks'
// range, the generator version it was drawn with; a screen's only from outside it), the shipped
// benchmark, the training screens and the validation screen load, the report's
// figures are the runs' means, and `swarmpath benchmark` reports per family and overall, with and
// without TA, beside the paper arenas, the same at any thread count, and says whether one params
// file beats another.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/benchmark_config.hpp"
#include "app/benchmark_report.hpp"
#include "sim/config_error.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::app {
namespace {

using cli_support::cli;
namespace fs = std::filesystem;

fs::path temp_dir() { return cli_support::temp_dir("cli_benchmark_test"); }

std::string read(const fs::path& p) { return cli_support::read_file(p); }

// the arena seeds of a benchmark file's families (of the row `label` alone where one is named)
std::set<std::uint64_t> arena_seeds(const BenchmarkConfig& c, const std::string& label = "") {
  std::set<std::uint64_t> seeds;
  for (const BenchmarkFamily& f : c.families) {
    if (label.empty() || f.label == label) seeds.insert(f.seeds.begin(), f.seeds.end());
  }
  return seeds;
}

// a screen's arenas: none drawn with a benchmark's seed
void expect_no_benchmark_seed(const BenchmarkConfig& c) {
  for (const std::uint64_t s : arena_seeds(c)) EXPECT_FALSE(sim::arenas::is_benchmark_seed(s)) << s;
}

// two families of small arenas, 8 robots, short runs
const std::string kTiny =
    "name = \"tiny\"\nversion = 3\ngenerator_version = 1\nrobots = [8]\nseeds = 1\nmax_ticks = 1500\n"
    "\n[[family]]\nfamily = \"open\"\nseeds = [1000001, 1000002]\n"
    "params = { width = 10, height = 8, distance_min = 3, distance_max = 4 }\n"
    "\n[[family]]\nfamily = \"wall-gap\"\nseeds = [1000003]\nparams = { width = 10, height = 8, door_min = "
    "1.5 }\n";

sim::ConfigError error_of(const std::string& text) {
  try {
    (void)parse_benchmark_config(text, "b.toml", "");
  } catch (const sim::ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return sim::ConfigError("", 0, "", "");
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return text.replace(pos, from.size(), to);
}

TEST(Benchmark, TheFileIsReadStrictly) {
  const BenchmarkConfig c = parse_benchmark_config(kTiny, "b.toml", "");
  EXPECT_EQ(c.version, 3);
  ASSERT_EQ(c.families.size(), 2u);
  EXPECT_EQ(c.arenas(), 3u);
  EXPECT_EQ(c.families[0].spec.param_values()("robots"), 8.0);  // drawn for the largest robot count
  sim::ConfigError e = error_of(with(kTiny, "1000002]", "2]"));
  EXPECT_EQ(std::string(e.what()).rfind(
                "b.toml:10: family[0].seeds: benchmark arenas take seeds in [1000000, 1999999]", 0),
            0u)
      << e.what();
  e = error_of(with(kTiny, "1000002]", "1000001]"));
  EXPECT_NE(std::string(e.what()).find("named twice"), std::string::npos) << e.what();
  e = error_of(with(kTiny, "generator_version = 1", "generator_version = 7"));
  EXPECT_EQ(e.key(), "generator_version");
  e = error_of(with(kTiny, "door_min = 1.5", "door_min = 9"));
  EXPECT_EQ(e.key(), "family[1].params.door_min");
  e = error_of(with(kTiny, "door_min = 1.5", "robots = 9"));
  EXPECT_EQ(e.key(), "family[1].params.robots");
  e = error_of(with(kTiny, "robots = [8]", "robots = [200]"));
  EXPECT_EQ(e.key(), "robots");
  e = error_of(kTiny.substr(0, kTiny.find("\n[[family]]")));
  EXPECT_EQ(e.key(), "family");
}

TEST(Benchmark, TheShippedBenchmarkLoads) {
  const BenchmarkConfig c =
      load_benchmark_config(std::string(SWARMPATH_SOURCE_DIR) + "/configs/benchmarks/generalisation.toml");
  EXPECT_EQ(c.name, "generalisation");
  EXPECT_EQ(c.families.size(), 8u);
  EXPECT_EQ(c.paper.size(), 8u);
  for (const BenchmarkFamily& f : c.families) {
    for (const std::uint64_t s : f.seeds) EXPECT_TRUE(sim::arenas::is_benchmark_seed(s));
  }
}

// a screen (purpose = "screen") is the training side: seeds outside the benchmarks' range only, and a
// family's rows may carry a label of their own (two wall-gap families, one with far doorways)
TEST(Benchmark, AScreenTakesOnlySeedsOutsideTheBenchmarksRangeAndLabelsItsRows) {
  std::string screen = with(kTiny, "version = 3\n", "version = 3\npurpose = \"screen\"\n");
  screen = with(screen, "[1000001, 1000002]", "[1, 2]");
  screen = with(screen, "[1000003]", "[3]\nlabel = \"wallfar\"");
  const BenchmarkConfig c = parse_benchmark_config(screen, "b.toml", "");
  EXPECT_TRUE(c.screen);
  EXPECT_EQ(c.families[0].label, "open");
  EXPECT_EQ(c.families[1].label, "wallfar");
  sim::ConfigError e = error_of(with(screen, "[1, 2]", "[1, 1000002]"));
  EXPECT_EQ(e.key(), "family[0].seeds");
  EXPECT_NE(std::string(e.what()).find("a screen's arenas take seeds outside the benchmarks' range"),
            std::string::npos)
      << e.what();
  EXPECT_EQ(error_of(with(screen, "\"screen\"", "\"tuning\"")).key(), "purpose");
  EXPECT_EQ(error_of(with(screen, "label = \"wallfar\"", "label = \"paper\"")).key(), "family[1].label");
  // a benchmark's seeds are its version: --seed-base only for a screen
  const fs::path dir = temp_dir();
  std::ofstream(dir / "screen.toml") << screen;
  std::ofstream(dir / "bench.toml") << kTiny;
  const auto rows = [&](const std::string& file, const std::string& base, const std::string& tag) {
    const auto r = cli({"benchmark", "--config", (dir / file).string(), "--no-paper", "--mode", "pf",
                        "--threads", "2", "--seed-base", base, "--json", (dir / (tag + ".json")).string()});
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(read(dir / (tag + ".json")));
  };
  const nlohmann::json a = rows("screen.toml", "1", "a");
  EXPECT_EQ(a["params"]["rows"][1]["arenas"], "wallfar");
  EXPECT_EQ(a["benchmark"]["arenas"][2]["family"], "wall-gap");
  EXPECT_EQ(a["benchmark"]["arenas"][2]["row"], "wallfar");
  EXPECT_EQ(a["benchmark"]["seed_base"], 1);
  EXPECT_EQ(rows("screen.toml", "5", "b")["benchmark"]["seed_base"], 5);
  const auto refused = cli({"benchmark", "--config", (dir / "bench.toml").string(), "--seed-base", "5"});
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("only a screen"), std::string::npos) << refused.err;
  EXPECT_EQ(cli({"benchmark", "--config", (dir / "screen.toml").string(), "--seed-base", "-1"}).code, 2);
}

TEST(Benchmark, TheShippedTrainingScreenLoads) {
  const BenchmarkConfig c =
      load_benchmark_config(std::string(SWARMPATH_SOURCE_DIR) + "/configs/benchmarks/training.toml");
  EXPECT_TRUE(c.screen);
  EXPECT_EQ(c.arenas(), 21u);
  EXPECT_EQ(c.paper.size(), 1u);  // env8
  expect_no_benchmark_seed(c);
}

// Version 2 holds version 1's arenas and more of each family, and no benchmark seed.
TEST(Benchmark, TheSecondTrainingScreenHoldsTheFirstsArenasAndMore) {
  const std::string dir = std::string(SWARMPATH_SOURCE_DIR) + "/configs/benchmarks/";
  const BenchmarkConfig v1 = load_benchmark_config(dir + "training.toml");
  const BenchmarkConfig v2 = load_benchmark_config(dir + "training-2.toml");
  EXPECT_TRUE(v2.screen);
  EXPECT_EQ(v2.version, 2);
  EXPECT_EQ(v2.arenas(), 42u);
  EXPECT_EQ(v2.paper.size(), 1u);  // env8
  for (const BenchmarkFamily& f : v1.families) {
    const std::set<std::uint64_t> wider = arena_seeds(v2, f.label);
    EXPECT_GT(wider.size(), f.seeds.size()) << f.label;
    for (const std::uint64_t s : f.seeds) EXPECT_TRUE(wider.count(s)) << f.label << " " << s;
  }
  expect_no_benchmark_seed(v2);
}

TEST(Benchmark, TheValidationScreenDrawsTheBenchmarksFamiliesFromOtherSeeds) {
  const std::string dir = std::string(SWARMPATH_SOURCE_DIR) + "/configs/benchmarks/";
  const BenchmarkConfig bench = load_benchmark_config(dir + "generalisation.toml");
  const BenchmarkConfig val = load_benchmark_config(dir + "validation.toml");
  const BenchmarkConfig train = load_benchmark_config(dir + "training-2.toml");
  EXPECT_TRUE(val.screen);
  EXPECT_TRUE(val.paper.empty());
  EXPECT_EQ(val.robots, bench.robots);
  EXPECT_EQ(val.max_ticks, bench.max_ticks);
  // every family of the benchmark, drawn as the benchmark draws it (its defaults), and no other
  ASSERT_EQ(val.families.size(), bench.families.size());
  for (std::size_t k = 0; k < bench.families.size(); ++k) {
    EXPECT_EQ(val.families[k].label, bench.families[k].label);
    EXPECT_TRUE(val.families[k].spec == bench.families[k].spec) << val.families[k].label;
    EXPECT_GE(val.families[k].seeds.size(), bench.families[k].seeds.size()) << val.families[k].label;
  }
  expect_no_benchmark_seed(val);
  const std::set<std::uint64_t> training_seeds = arena_seeds(train);
  for (const std::uint64_t s : arena_seeds(val))
    EXPECT_FALSE(training_seeds.count(s)) << s;  // no training arena
  EXPECT_EQ(val.arenas(), 62u);
}

sim::Metrics run_metrics(bool success, std::int64_t ticks, double path) {
  sim::Metrics m;
  m.success = success;
  m.ticks = success ? ticks : 1000;
  m.ticks_to_form = success ? ticks : -1;
  m.path_length_tu = success ? path : std::nan("");
  return m;
}

TEST(Benchmark, RowsAreTheMeansOfTheirRuns) {
  // two arenas of "open", one paper arena; A* 10 TU each
  const std::vector<std::string> groups = {"open"}, group_of = {"open", "open", "paper"};
  const std::vector<double> astar = {10.0, 10.0, 10.0};
  const auto run = [](std::size_t s, bool ok, std::int64_t t, double path) {
    return GridRun{{s, 8, sim::Mode::kPathFormation, 1}, run_metrics(ok, t, path)};
  };
  const std::vector<GridRun> runs = {run(0, true, 100, 11.0), run(1, false, 0, 0.0), run(1, true, 300, 12.0),
                                     run(2, true, 50, 10.0)};
  const std::vector<BenchmarkRow> rows = benchmark_rows(groups, group_of, astar, runs);
  ASSERT_EQ(rows.size(), 3u);  // open, all families, paper arenas
  EXPECT_EQ(rows[0].group, "open");
  EXPECT_EQ(rows[0].arenas, 2);
  EXPECT_DOUBLE_EQ(rows[0].pf.success_rate, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(rows[0].pf.ticks, 200.0);                              // over the successes
  EXPECT_DOUBLE_EQ(rows[0].pf.ticks_censored, (100 + 1000 + 300) / 3.0);  // a failure at its T_max
  EXPECT_DOUBLE_EQ(rows[0].pf.path_ratio, 1.15);
  EXPECT_EQ(rows[1].group, "all families");
  EXPECT_EQ(rows[1].pf.runs, 3);
  EXPECT_EQ(rows[2].group, "paper arenas");
  EXPECT_DOUBLE_EQ(rows[2].pf.ticks, 50.0);
  EXPECT_EQ(rows[0].ta.runs, 0);
  // A against B: the paired time is over the runs both formed
  std::vector<GridRun> other = runs;
  other[0].m = run_metrics(true, 80, 10.0);
  other[1].m = run_metrics(true, 90, 10.0);
  const std::vector<BenchmarkDifference> d = benchmark_differences(groups, group_of, runs, other);
  EXPECT_EQ(d[0].pf.both, 2);
  EXPECT_EQ(d[0].pf.only_b, 1);
  EXPECT_DOUBLE_EQ(d[0].pf.ticks_a, 200.0);
  EXPECT_DOUBLE_EQ(d[0].pf.ticks_b, 190.0);  // runs 0 and 2: 80 and 300
  const Verdict v =
      benchmark_verdict(rows[1], benchmark_rows(groups, group_of, astar, other)[1], d[1], true, false);
  EXPECT_FALSE(v.wins);
  const Verdict w = benchmark_verdict(benchmark_rows(groups, group_of, astar, other)[1], rows[1],
                                      benchmark_differences(groups, group_of, other, runs)[1], true, false);
  EXPECT_TRUE(w.wins) << w.text;
}

TEST(Benchmark, TheCommandReportsPerFamilyAndOverallTheSameAtAnyThreadCount) {
  const fs::path dir = temp_dir();
  std::string tiny = kTiny;
  tiny.insert(tiny.find("\n[[family]]"),
              std::string("paper = \"") + SWARMPATH_SOURCE_DIR + "/tests/data\"\n");
  std::ofstream(dir / "tiny.toml") << tiny;
  const std::string genome = std::string(SWARMPATH_SOURCE_DIR) + "/genomes/default.toml";
  const auto run = [&](const std::string& threads, const std::string& tag) {
    return cli({"benchmark", "--config", (dir / "tiny.toml").string(), "--params", genome, "--against",
                genome, "--threads", threads, "--json", (dir / (tag + ".json")).string(), "--svg",
                (dir / (tag + ".svg")).string(), "--md", (dir / (tag + ".md")).string()});
  };
  const auto one = run("1", "one");
  ASSERT_EQ(one.code, 0) << one.err;
  const auto two = run("2", "two");
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_EQ(one.out, two.out);
  nlohmann::json a = nlohmann::json::parse(read(dir / "one.json")),
                 b = nlohmann::json::parse(read(dir / "two.json"));
  EXPECT_EQ(a, b);
  EXPECT_EQ(read(dir / "one.md"), one.out);
  EXPECT_EQ(read(dir / "one.svg").rfind("<svg", 0), 0u);
  // per family, all families, the paper arenas; with and without TA
  const nlohmann::json& rows = a["params"]["rows"];
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0]["arenas"], "open");
  EXPECT_EQ(rows[0]["n"], 2);
  EXPECT_EQ(rows[2]["arenas"], "all families");
  EXPECT_EQ(rows[3]["arenas"], "paper arenas");
  EXPECT_EQ(rows[2]["pf"]["runs"], 3);
  EXPECT_EQ(rows[2]["ta"]["runs"], 3);
  EXPECT_EQ(a["benchmark"]["arenas"].size(), 3u);
  EXPECT_EQ(a["benchmark"]["arenas"][2]["family"], "wall-gap");
  // the same params on the same runs cannot beat themselves
  EXPECT_FALSE(a["verdict"]["params_beats_against"].get<bool>());
  EXPECT_NE(one.out.find("A does not beat B"), std::string::npos);
  EXPECT_NE(one.out.find("| **all families** | 3 |"), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("The paper arenas with"), std::string::npos);
  // one family only, no paper arenas, one mode
  const auto r = cli({"benchmark", "--config", (dir / "tiny.toml").string(), "--families", "wall-gap",
                      "--no-paper", "--mode", "pf", "--threads", "2"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.find("with TA"), std::string::npos);
  EXPECT_EQ(cli({"benchmark", "--config", (dir / "tiny.toml").string(), "--families", "rooms"}).code, 2);
}

TEST(Benchmark, EveryOutputThatCanBeWrittenIsWrittenAndTheOneThatCannotIsNamed) {
  const fs::path dir = temp_dir() / "full";
  fs::create_directories(dir);
  std::ofstream(dir / "tiny.toml") << kTiny;
  const auto r = cli({"benchmark", "--config", (dir / "tiny.toml").string(), "--families", "wall-gap",
                      "--no-paper", "--mode", "pf", "--threads", "1", "--svg", (dir / "b.svg").string(),
                      "--json", "/dev/full", "--md", (dir / "b.md").string()});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("cannot write /dev/full"), std::string::npos) << r.err;
  EXPECT_EQ(read(dir / "b.svg").rfind("<svg", 0), 0u);
  ASSERT_TRUE(fs::exists(dir / "b.md"));  // written after the failed JSON
  EXPECT_EQ(read(dir / "b.md"), r.out);
  EXPECT_NE(r.out.find("wall-gap"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace swarmpath::app
