// SPDX-License-Identifier: MIT
// The ablation: paired effects and their verdicts, and `swarmpath ablate` on a small arena (rows per
// arm and mode, the cache, bad input).
#include "app/ablation.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "sim/additions.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::app {
namespace {

namespace fs = std::filesystem;
using cli_support::cli;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

RunOutcome ok(double ticks, double path, double rr = kNaN) { return {true, ticks, path, rr, 0}; }

RunOutcome failed(double rr = kNaN) { return {false, kNaN, kNaN, rr, 0}; }

TEST(Ablation, PairedEffectIsWithMinusWithoutOverTheRightPairs) {
  const std::vector<RunOutcome> with = {ok(100, 1.0, 50), ok(200, 1.1, 60), ok(300, 1.2, 40), failed(30)};
  const std::vector<RunOutcome> without = {ok(150, 1.2, 40), failed(30), ok(330, 1.2, 40), failed(20)};
  const Effect e = paired_effect(with, without);
  EXPECT_EQ(e.pairs, 4);
  EXPECT_DOUBLE_EQ(e.success_with, 0.75);
  EXPECT_DOUBLE_EQ(e.success_without, 0.5);
  EXPECT_EQ(e.success.n, 4);
  EXPECT_DOUBLE_EQ(e.success.mean, 0.25);  // (0 + 1 + 0 + 0) / 4
  EXPECT_EQ(e.ticks.n, 2);                 // the pairs where both formed the path
  EXPECT_DOUBLE_EQ(e.ticks.mean, -40.0);   // (-50 - 30) / 2
  EXPECT_NEAR(e.path_ratio.mean, -0.1, 1e-12);
  EXPECT_EQ(e.rr_pct.n, 4);
  EXPECT_DOUBLE_EQ(e.rr_pct.mean, 12.5);  // (10 + 30 + 0 + 10) / 4
  EXPECT_THROW(paired_effect(with, std::vector<RunOutcome>(3)), std::invalid_argument);
}

TEST(Ablation, VerdictNeedsAnIntervalThatExcludesZero) {
  Effect e;
  e.success = {0.2, 0.1, 40};  // [0.1, 0.3]: more success
  EXPECT_EQ(verdict_of(e), Verdict::kHelps);
  e.ticks = {500.0, 200.0, 30};  // [300, 700] ticks slower
  EXPECT_EQ(verdict_of(e), Verdict::kMixed);
  e.success = {0.2, 0.3, 40};  // [-0.1, 0.5]: includes zero
  EXPECT_EQ(verdict_of(e), Verdict::kHurts);
  e.ticks = {-500.0, 600.0, 30};
  EXPECT_EQ(verdict_of(e), Verdict::kNotMeasurable);
  e.path_ratio = {-0.05, 0.01, 1};  // one pair: no interval
  EXPECT_EQ(verdict_of(e), Verdict::kNotMeasurable);
}

fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir =
      fs::temp_directory_path() / ("swarmpath_ablation_test_" + std::to_string(::getpid())) / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string source(const std::string& rel) { return std::string(SWARMPATH_SOURCE_DIR) + "/" + rel; }

std::vector<std::string> small_ablation(const fs::path& dir, const std::string& arms,
                                        const std::string& options) {
  return {"ablate",
          "--params",
          source("genomes/default.toml"),
          "--literal",
          source("genomes/paper-literal.toml"),
          "--scenarios",
          source("tests/data/short_chain.toml"),
          "--robots",
          "12",
          "--seeds",
          "2",
          "--ticks",
          "1500",
          "--threads",
          "2",
          "--arms",
          arms,
          "--options",
          options,
          "--cache",
          (dir / "cache").string(),
          "--json",
          (dir / "a.json").string(),
          "--svg",
          (dir / "a.svg").string()};
}

nlohmann::json read_json(const fs::path& p) {
  std::ifstream f(p);
  return nlohmann::json::parse(f);
}

TEST(AblateCli, ListsEveryAddition) {
  const auto r = cli({"ablate", "--list"});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const sim::Addition& a : sim::additions())
    EXPECT_NE(r.out.find("  " + std::string(a.name) + ": "), std::string::npos) << a.name;
}

TEST(AblateCli, RowsPerArmAndModeAndTheCacheGivesTheSameTable) {
  const fs::path dir = scratch();
  const auto first = cli(small_ablation(dir, "default,literal", "w_seek,depart_gap"));
  ASSERT_EQ(first.code, 0) << first.err;
  const nlohmann::json j = read_json(dir / "a.json");
  // w_seek acts in both modes, depart_gap in task allocation only: 3 rows per arm
  ASSERT_EQ(j["rows"].size(), 6u);
  EXPECT_EQ(j["rows"][0]["arm"], "default");
  EXPECT_EQ(j["rows"][0]["addition"], "w_seek");
  EXPECT_EQ(j["rows"][0]["mode"], "pf");
  EXPECT_EQ(j["rows"][2]["addition"], "depart_gap");
  EXPECT_EQ(j["rows"][2]["mode"], "ta");
  EXPECT_EQ(j["rows"][3]["arm"], "literal");
  for (const auto& row : j["rows"]) EXPECT_EQ(row["pairs"], 2);
  EXPECT_NE(first.out.find("| `w_seek`"), std::string::npos);
  std::ifstream svg(dir / "a.svg");
  std::stringstream s;
  s << svg.rdbuf();
  EXPECT_EQ(s.str().rfind("<svg", 0), 0u);
  // again: every variant from the cache, the same rows
  const auto again = cli(small_ablation(dir, "default,literal", "w_seek,depart_gap"));
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.err.find("4 variants from the cache"), std::string::npos) << again.err;
  EXPECT_EQ(read_json(dir / "a.json"), j);
  // --modes both is pf and ta: the same runs, so the same cache entries and rows
  std::vector<std::string> both = small_ablation(dir, "default,literal", "w_seek,depart_gap");
  both.insert(both.end(), {"--modes", "both"});
  const auto with_both = cli(both);
  ASSERT_EQ(with_both.code, 0) << with_both.err;
  EXPECT_NE(with_both.err.find("4 variants from the cache"), std::string::npos) << with_both.err;
  EXPECT_EQ(read_json(dir / "a.json"), j);
}

TEST(AblateCli, RejectsAnUnknownAdditionOrArm) {
  const fs::path dir = scratch();
  EXPECT_EQ(cli(small_ablation(dir, "default", "no_such_thing")).code, 2);
  EXPECT_EQ(cli(small_ablation(dir, "sideways", "w_seek")).code, 2);
}

}  // namespace
}  // namespace swarmpath::app
