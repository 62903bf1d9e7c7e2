// SPDX-License-Identifier: MIT
// `swarmpath report`: the per-generation tuned values the runners book (and checkpoints keep), the
// page's sections for CMA-ES and NSGA-II runs, its intervals, its replays and its errors. The page
// in a browser: tests/web/report_test.mjs.
#include "app/report_page.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/web_page.hpp"
#include "evolve/checkpoint.hpp"
#include "evolve/genome.hpp"
#include "evolve/runner.hpp"
#include "evolve_test_support.hpp"
#include "sim/recording.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::evolve {
namespace {

using app::cli_support::cli;
using testing::read_text;
using testing::scratch;
using testing::write_text;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// the tiny CMA-ES run through the command line into `dir`; returns the config's path
std::string evolve_tiny(const std::filesystem::path& dir, const std::string& text) {
  const std::string config = (dir / "tiny.toml").string();
  write_text(config, text);
  const auto r = cli({"evolve", "--config", config, "--out", (dir / "run").string(), "--threads", "2"});
  EXPECT_EQ(r.code, 0) << r.err;
  return config;
}

TEST(ReportValues, RunnersBookEachGenerationsTunedValuesAndCheckpointsKeepThem) {
  const auto dir = scratch("cmaes");
  evolve_tiny(dir, testing::tiny_config("cmaes", 3));
  const EvolveConfig c = parse_evolve_config(testing::tiny_config("cmaes", 3), "tiny.toml", "");
  const RunState st = read_checkpoint((dir / "run" / "checkpoint.json").string());
  ASSERT_EQ(st.history.size(), 3U);
  for (const GenerationRecord& r : st.history) {
    ASSERT_EQ(r.tuned_best.size(), c.genome.genes.size());
    ASSERT_EQ(r.tuned_mean.size(), c.genome.genes.size());
    for (std::size_t k = 0; k < c.genome.genes.size(); ++k) {
      const Gene& g = c.genome.genes[k];
      EXPECT_LE(r.tuned_min[k], r.tuned_mean[k] + 1e-12) << g.info->name;
      EXPECT_LE(r.tuned_mean[k], r.tuned_max[k] + 1e-12);
      EXPECT_GE(r.tuned_min[k], g.lo - 1e-9);
      EXPECT_LE(r.tuned_max[k], g.hi + 1e-9);
      EXPECT_GE(r.tuned_best[k], r.tuned_min[k]);
      EXPECT_LE(r.tuned_best[k], r.tuned_max[k]);
    }
  }
  EXPECT_NE(st.history[0].tuned_mean, st.history[2].tuned_mean) << "the population moved";
  // a checkpoint written before these values existed still reads (and resumes)
  nlohmann::json j = nlohmann::json::parse(read_text(dir / "run" / "checkpoint.json"));
  for (auto& r : j["history"]) {
    for (const char* key : {"tuned_best", "tuned_mean", "tuned_min", "tuned_max"}) r.erase(key);
  }
  const RunState old = checkpoint_from_json(j);
  EXPECT_EQ(old.history.size(), 3U);
  EXPECT_TRUE(old.history[0].tuned_mean.empty());
}

TEST(ReportValues, BookTunedValuesSkipsCandidatesWithAViolation) {
  const EvolveConfig c = testing::tiny();
  std::vector<Decoded> decoded(3, Decoded{c.genome.base, false, {}});
  decoded[0].params.w_away = 0.2;
  decoded[1].params.w_away = 0.6;
  decoded[2].params.w_away = 9.0;
  decoded[2].violation = "broken";
  GenerationRecord rec;
  book_tuned_values(rec, c.genome, decoded, 1);
  std::size_t k = 0;
  while (k < c.genome.genes.size() && c.genome.genes[k].info->name != "w_away") ++k;
  ASSERT_LT(k, c.genome.genes.size());
  EXPECT_DOUBLE_EQ(rec.tuned_best[k], 0.6);
  EXPECT_DOUBLE_EQ(rec.tuned_mean[k], 0.4);
  EXPECT_DOUBLE_EQ(rec.tuned_min[k], 0.2);
  EXPECT_DOUBLE_EQ(rec.tuned_max[k], 0.6);
  GenerationRecord none;
  book_tuned_values(none, c.genome, decoded, std::nullopt);
  EXPECT_TRUE(none.tuned_best.empty());
}

TEST(ReportPage, ACmaesRunWithoutAndWithEvaluateJsonAndReplays) {
  const auto dir = scratch("page");
  const std::string config = evolve_tiny(dir, testing::tiny_config("cmaes", 2));
  const std::string run = (dir / "run").string();
  // without replays and without evaluate.json: every section, the re-evaluation means and a note
  const auto a = cli({"report", run, "--no-replays"});
  ASSERT_EQ(a.code, 0) << a.err;
  const std::string page = read_text(dir / "run" / "report.html");
  for (const char* id : {"progress", "parameters", "comparison", "replays", "provenance"})
    EXPECT_NE(page.find(std::string("<section id=\"") + id + "\""), std::string::npos) << id;
  EXPECT_EQ(page.find("id=\"pareto\""), std::string::npos);
  EXPECT_EQ(count(page, "<figure>"), 3U) << "one chart per tuned parameter";
  EXPECT_NE(page.find("has no <code>evaluate.json</code>"), std::string::npos);
  EXPECT_NE(page.find("No replays in this report"), std::string::npos);
  EXPECT_EQ(page.find("{{"), std::string::npos);
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_NE(page.find(read_text(dir / "run" / "best.toml").substr(0, 40)), std::string::npos)
      << "the genome's text is in the page";

  // with evaluate.json: the table with intervals
  const auto e =
      cli({"evaluate", "--params", run + "/best.toml", "--against", testing::source("genomes/default.toml"),
           "--scenarios", testing::source("tests/data/short_chain.toml"), "--robots", "20", "--seeds", "3",
           "--ticks", "8000", "--json", run + "/evaluate.json"});
  ASSERT_EQ(e.code, 0) << e.err;
  // with replays: the reported genome on the run's arena, recorded
  const auto b = cli({"report", run, "--config", config, "--out", (dir / "full.html").string()});
  ASSERT_EQ(b.code, 0) << b.err;
  const std::string full = read_text(dir / "full.html");
  EXPECT_EQ(full.find("has no <code>evaluate.json</code>"), std::string::npos);
  EXPECT_NE(full.find("<td><b>overall</b></td>"), std::string::npos);
  EXPECT_GE(count(full, " ± "), 6U);
  EXPECT_EQ(count(full, "<script type=\"application/x-swrec\" data-title="), 1U) << "one arena, one replay";
  EXPECT_NE(full.find("short_chain, 8 robots, seed "), std::string::npos);
  // without the config: a note, no replays, still a page
  const auto c =
      cli({"report", run, "--config", (dir / "missing.toml").string(), "--out", (dir / "x.html").string()});
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.err.find("No replays"), std::string::npos);
}

TEST(ReportPage, ANsga2RunHasItsFrontAndHypervolume) {
  const auto dir = scratch("nsga2");
  evolve_tiny(dir, testing::tiny_pareto_config(2));
  const auto r = cli({"report", (dir / "run").string(), "--no-replays"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string page = read_text(dir / "run" / "report.html");
  EXPECT_NE(page.find("Hypervolume per generation"), std::string::npos);
  EXPECT_NE(page.find("<section id=\"pareto\">"), std::string::npos);
  const nlohmann::json run = nlohmann::json::parse(read_text(dir / "run" / "run.json"));
  const std::size_t pareto_at = page.find("<section id=\"pareto\">");
  const std::string pareto = page.substr(pareto_at, page.find("</section>", pareto_at) - pareto_at);
  EXPECT_EQ(count(pareto, "<tr><td>"), run["front"].size() + 1) << "every front point and the base";
  EXPECT_NE(page.find("front/000.toml"), std::string::npos);
}

TEST(ReportPage, BadFoldersAreRejectedWithExitTwo) {
  const auto dir = scratch("bad");
  const auto missing = cli({"report", (dir / "nowhere").string()});
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("not a folder"), std::string::npos) << missing.err;
  const auto unfinished = cli({"report", dir.string()});
  EXPECT_EQ(unfinished.code, 2);
  EXPECT_NE(unfinished.err.find("run.json: missing"), std::string::npos) << unfinished.err;
  write_text(dir / "run.json", "{ not json");
  const auto broken = cli({"report", dir.string()});
  EXPECT_EQ(broken.code, 2);
  EXPECT_NE(broken.err.find("not valid JSON"), std::string::npos) << broken.err;
}

TEST(ReportPage, IntervalsAreStudentsAndWilsons) {
  const app::MeanInterval m = app::mean_interval({1.0, 2.0, 3.0, std::nan("")});
  EXPECT_EQ(m.n, 3);
  EXPECT_DOUBLE_EQ(m.mean, 2.0);
  EXPECT_NEAR(m.half_width, 4.302653 / std::sqrt(3.0), 1e-4);  // t(0.975, 2) s / sqrt(n), s = 1
  EXPECT_TRUE(std::isinf(app::mean_interval({5.0}).half_width));
  const auto [lo, hi] = app::wilson_interval(3, 3);
  EXPECT_NEAR(lo, 0.4385, 1e-4);  // 3 of 3: Wilson's interval [0.44, 1]
  EXPECT_DOUBLE_EQ(hi, 1.0);
  const auto [lo2, hi2] = app::wilson_interval(5, 10);
  EXPECT_NEAR(lo2, 0.2366, 1e-4);
  EXPECT_NEAR(hi2, 0.7634, 1e-4);
}

}  // namespace
}  // namespace swarmpath::evolve
