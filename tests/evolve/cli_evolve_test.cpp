// SPDX-License-Identifier: MIT
// The evolve, evaluate and export commands: help, exit code 2 with file:line for bad configs,
// the files an evolve run writes, paired evaluation, and the export formats.
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "evolve/genome.hpp"
#include "evolve_test_support.hpp"
#include "sim/params.hpp"
#include "tests/app/cli_support.hpp"

namespace swarmpath::app {
namespace {

using evolve::testing::read_text;
using evolve::testing::scratch;
using evolve::testing::source;
using evolve::testing::write_text;

using Result = cli_support::CliResult;
using cli_support::cli;

TEST(CliEvolve, HelpForEachCommand) {
  Result r = cli({"--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* cmd : {"evolve", "evaluate", "export"})
    EXPECT_NE(r.out.find(cmd), std::string::npos) << cmd;
  r = cli({"evolve", "--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* opt : {"--config", "--out", "--threads", "--generations", "--resume"}) {
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  }
  r = cli({"evaluate", "--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* opt : {"--params", "--scenarios", "--robots", "--seeds", "--seed-base", "--mode",
                          "--threads", "--json", "--against"}) {
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  }
  r = cli({"export", "--help"});
  EXPECT_EQ(r.code, 0);
  for (const char* opt : {"--params", "--format", "--out"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

TEST(CliEvolve, BadConfigExitsWithTwoAndNamesFileAndLine) {
  const auto dir = scratch("cfg");
  std::string text = evolve::testing::tiny_config();
  text.replace(text.find("w_away = {}"), 11, "w_away = { hi = 9 }");
  const int line =
      1 + static_cast<int>(std::count(text.begin(),
                                      text.begin() + static_cast<std::ptrdiff_t>(text.find("hi = 9")), '\n'));
  write_text(dir / "bad.toml", text);
  const Result r = cli({"evolve", "--config", (dir / "bad.toml").string(), "--out", (dir / "out").string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad.toml:" + std::to_string(line) + ": tune.w_away.hi: "), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  EXPECT_EQ(cli({"evolve", "--config", "/no/such/config.toml"}).code, 2);
  EXPECT_EQ(cli({"evolve"}).code, 2);  // --config is required
  EXPECT_EQ(cli({"evolve", "--config", (dir / "bad.toml").string(), "--generations", "0"}).code, 2);
}

TEST(CliEvolve, EvolveWritesItsFilesAndResumes) {
  const auto dir = scratch("run");
  write_text(dir / "tiny.toml", evolve::testing::tiny_config("cmaes", 2));
  const std::string out = (dir / "out").string();
  Result r = cli({"evolve", "--config", (dir / "tiny.toml").string(), "--out", out, "--threads", "2",
                  "--generations", "1", "--no-wall-time"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("generation 0/1: best "), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("(best)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("base params"), std::string::npos) << r.out;
  for (const char* f : {"log.csv", "best.toml", "run.json", "fitness.svg", "checkpoint.json"}) {
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(out) / f)) << f;
  }
  // best.toml is a params file usable everywhere
  const std::string best = (std::filesystem::path(out) / "best.toml").string();
  // its header says whether the base params were kept (keep_base, the default) and the test's figures
  const nlohmann::json first = nlohmann::json::parse(read_text(std::filesystem::path(out) / "run.json"));
  const bool kept = first.at("selection").at("base_kept").get<bool>();
  EXPECT_EQ(read_text(best).rfind(kept ? "# swarmpath evolve: the base params kept by run"
                                       : "# swarmpath evolve: the best candidate of run",
                                  0),
            0u);
  EXPECT_NE(read_text(best).find("one-sided p = "), std::string::npos);
  EXPECT_NE(r.out.find("keep_base: base minus best finalist"), std::string::npos) << r.out;
  (void)sim::load_params(best);
  r = cli({"simulate", "--scenario", source("tests/data/short_chain.toml"), "--params", best, "--mode", "pf",
           "--robots", "8", "--ticks", "500"});
  EXPECT_EQ(r.code, 0) << r.err;
  // resume one more generation
  r = cli({"evolve", "--config", (dir / "tiny.toml").string(), "--out", out, "--threads", "1",
           "--generations", "2", "--resume", "--no-wall-time"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("resuming"), std::string::npos) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_text(std::filesystem::path(out) / "run.json"));
  EXPECT_EQ(j.at("generations").get<int>(), 2);
}

TEST(CliEvolve, Nsga2WritesTheFrontAndExportTakesAnyPoint) {
  const auto dir = scratch("pareto");
  write_text(dir / "tiny.toml", evolve::testing::tiny_pareto_config(2));
  const std::filesystem::path out = dir / "out";
  Result r = cli({"evolve", "--config", (dir / "tiny.toml").string(), "--out", out.string(), "--threads", "2",
                  "--no-wall-time"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("generation 1/2: hypervolume "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("re-evaluating the "), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("| point | found | success | path / A* | ticks to form | robots used / N | note |"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("| base params |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("front points dominate the base params"), std::string::npos) << r.out;
  for (const char* f : {"log.csv", "hypervolume.svg", "pareto.csv", "pareto.svg", "run.json",
                        "checkpoint.json", "front/000.toml"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  EXPECT_FALSE(std::filesystem::exists(out / "best.toml"));  // a front has no single best
  // every front point exports, e.g. as ARGoS controller attributes
  const nlohmann::json j = nlohmann::json::parse(read_text(out / "run.json"));
  ASSERT_FALSE(j.at("front").empty());
  for (const nlohmann::json& p : j.at("front")) {
    const std::string file = (out / p.at("params_file").get<std::string>()).string();
    r = cli({"export", "--params", file, "--format", "argos"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(
        r.out.find(" w_away=\"" + sim::format_value(sim::load_params(file), *sim::find_param("w_away"))),
        std::string::npos)
        << r.out;
  }
}

TEST(CliEvolve, EvaluateAgainstRunsBothOnTheSameSeeds) {
  const auto dir = scratch("eval");
  const std::string json = (dir / "eval.json").string();
  const Result r =
      cli({"evaluate", "--params", source("genomes/default.toml"), "--against",
           source("genomes/default.toml"), "--scenarios", source("tests/data/short_chain.toml"), "--robots",
           "8", "--seeds", "3", "--ticks", "4000", "--threads", "2", "--json", json});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("paired"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("**overall**"), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(read_text(json));
  const auto& p = j.at("paired");
  // the same params on the same seeds: identical runs
  EXPECT_EQ(p.at("params_faster").get<int>(), 0);
  EXPECT_EQ(p.at("against_faster").get<int>(), 0);
  EXPECT_EQ(p.at("equal").get<int>(), p.at("both_succeeded").get<int>());
  EXPECT_EQ(p.at("only_params").get<int>() + p.at("only_against").get<int>(), 0);
  EXPECT_EQ(p.at("both_succeeded").get<int>() + p.at("neither").get<int>(), 3);
  EXPECT_EQ(j.at("runs").size(), 3u);
  ASSERT_EQ(j.at("cases").size(), 1u);  // one (scenario, robots) group
  EXPECT_EQ(j.at("cases")[0].at("robots").get<int>(), 8);
  EXPECT_EQ(j.at("cases")[0].at("params").at("runs").get<int>(), 3);
  EXPECT_EQ(j.at("overall").at("params"), j.at("overall").at("against"));
  // seeds are seed-base ... seed-base + seeds - 1
  EXPECT_EQ(j.at("runs")[2].at("seed").get<int>(), 3);
  EXPECT_EQ(cli({"evaluate", "--params", source("genomes/default.toml"), "--mode", "diffusion"}).code, 2);
}

TEST(CliEvolve, ExportFormats) {
  const auto dir = scratch("export");
  // a params file far from the defaults
  evolve::Genome g;
  for (const sim::ParamInfo& info : sim::param_table()) g.genes.push_back(evolve::default_gene(info));
  evolve::Vector x(g.dim(), 0.37);
  const sim::Params p = evolve::decode(g, x).params;
  {
    std::ostringstream s;
    sim::write_params_toml(s, p);
    write_text(dir / "in.toml", s.str());
  }
  const std::string in = (dir / "in.toml").string();
  Result r = cli({"export", "--params", in, "--format", "toml", "--out", (dir / "out.toml").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const sim::Params back = sim::load_params((dir / "out.toml").string());
  for (const sim::ParamInfo& info : sim::param_table()) {
    EXPECT_EQ(sim::get_value(back, info), sim::get_value(p, info)) << info.name;
  }
  r = cli({"export", "--params", in, "--format", "json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.size(), sim::param_table().size());
  EXPECT_EQ(j.at("v_max").at("value").get<double>(), p.v_max);
  EXPECT_EQ(j.at("v_max").at("unit").get<std::string>(), "cm/s");
  r = cli({"export", "--params", in, "--format", "argos"});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const sim::ParamInfo& info : sim::param_table()) {
    EXPECT_NE(r.out.find(" " + std::string(info.name) + "=\""), std::string::npos) << info.name;
  }
  r = cli({"export", "--params", in, "--format", "yaml"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("yaml"), std::string::npos);
}

}  // namespace
}  // namespace swarmpath::app
