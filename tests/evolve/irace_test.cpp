// SPDX-License-Identifier: MIT
// The irace interop: the simulation budget an outside tuner gets, the parameter and instance lines
// of the scenario, the manifest, and elites.csv read back into params with provenance. (irace
// itself runs in tests/python/test_irace_real.py.)
#include <filesystem>

#include <gtest/gtest.h>

#include "evolve/irace_import.hpp"
#include "evolve/irace_scenario.hpp"
#include "evolve/simulation_budget.hpp"
#include "evolve_test_support.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::evolve {
namespace {

using testing::read_text;
using testing::scratch;
using testing::source;
using testing::write_text;

EvolveConfig tiny() { return load_evolve_config(source("tests/data/tune/tiny_tune.toml")); }

TEST(SimulationBudget, CandidatesTimesCasesPlusTheFinalists) {
  const EvolveConfig c = tiny();  // CMA-ES on 2 genes: population 4 + floor(3 ln 2) = 6
  const auto b = simulation_budget(c);
  ASSERT_TRUE(b);
  EXPECT_EQ(b->population, 6);
  EXPECT_EQ(b->candidates, 8 * 6);
  EXPECT_EQ(b->cases_per_candidate, 2);  // 1 scenario x 1 robot count x 2 seeds
  EXPECT_EQ(b->reevaluation, 2 * 3);     // (top_k 1 + the base params, keep_base) x 3 fresh seeds
  EXPECT_EQ(b->total, 102);
  EvolveConfig without_base = c;  // without keep_base the base params' runs choose nothing: not counted
  without_base.reevaluate.keep_base = false;
  EXPECT_EQ(simulation_budget(without_base)->reevaluation, 1 * 3);
  EvolveConfig e = c;
  e.budget.evaluations = 20;  // stops after the generation that reaches 20: 4 x 6
  EXPECT_EQ(simulation_budget(e)->candidates, 24);
  e.budget = Budget{0, 0, 60.0};
  EXPECT_FALSE(simulation_budget(e));
}

TEST(IraceScenario, ParameterLinesCarryTypesRangesAndLogScales) {
  const EvolveConfig c = load_evolve_config(source("configs/evolve/default.toml"));
  const std::vector<std::string> lines = irace_parameter_lines(c.genome);
  ASSERT_EQ(lines.size(), 6u);
  const auto fields = [](const std::string& l) {
    std::istringstream in(l);
    std::vector<std::string> f;
    for (std::string w; in >> w;) f.push_back(w);
    return f;
  };
  EXPECT_EQ(fields(lines[0]),
            (std::vector<std::string>{"T_explore0", "\"--T_explore0=\"", "i", "(200,", "3000)", "#",
                                      "rounded", "to", "lo", "+", "k", "*", "50"}));
  EXPECT_EQ(fields(lines[2]), (std::vector<std::string>{"w_away", "\"--w_away=\"", "r", "(0,", "2)"}));
  EXPECT_EQ(fields(lines[4]),
            (std::vector<std::string>{"p_turn", "\"--p_turn=\"", "r,log", "(0.002,", "0.2)"}));
  Genome g;
  g.genes = {default_gene(*sim::find_param("revert_orphans")), default_gene(*sim::find_param("t_source")),
             default_gene(*sim::find_param("T_lost"))};
  const std::vector<std::string> more = irace_parameter_lines(g);
  EXPECT_EQ(fields(more[0])[2] + fields(more[0])[3] + fields(more[0])[4], "c(false,true)");
  EXPECT_EQ(fields(more[1])[2] + fields(more[1])[3] + fields(more[1])[4], "c(budget,elapsed)");
  EXPECT_EQ(fields(more[2])[2] + fields(more[2])[3] + fields(more[2])[4], "i(1,20)");
}

TEST(IraceScenario, WritesEveryFileAndTheManifestReadsBack) {
  const EvolveConfig c = tiny();
  const auto dir = scratch("irace");
  IraceScenarioOptions o;
  o.out_dir = dir.string();
  o.swarmpath = "/opt/it's here/swarmpath";
  o.parallel = 4;
  const IraceManifest m = write_irace_scenario(c, o);
  EXPECT_EQ(m.max_experiments, 102);
  EXPECT_EQ(m.seed, c.seed);
  ASSERT_EQ(m.instances.size(), 1u);
  EXPECT_EQ(m.instances[0],
            std::filesystem::absolute(source("tests/data/short_chain.toml")).lexically_normal().string() +
                " --robots 20");
  const std::string scenario = read_text(dir / "scenario.txt");
  EXPECT_NE(scenario.find("maxExperiments = 102\n"), std::string::npos);
  EXPECT_NE(scenario.find("parallel = 4\n"), std::string::npos);
  EXPECT_NE(scenario.find("trainInstancesDir = \"\"\n"), std::string::npos);
  // the binary's path is quoted for sh, a quote in it too
  EXPECT_NE(read_text(dir / "target-runner").find("exec '/opt/it'\\''s here/swarmpath' irace run"),
            std::string::npos);
  EXPECT_NE(std::filesystem::status(dir / "target-runner").permissions() & std::filesystem::perms::owner_exec,
            std::filesystem::perms::none);
  const IraceManifest back = read_irace_manifest(dir.string());
  EXPECT_EQ(back.config, m.config);
  EXPECT_EQ(back.config_hash, config_hash(c));
  EXPECT_EQ(back.instances, m.instances);
  o.max_experiments = 500;
  EXPECT_EQ(write_irace_scenario(c, o).max_experiments, 500);
}

TEST(IraceScenario, RefusesWhatIraceCannotTake) {
  EvolveConfig c = load_evolve_config(source("configs/evolve/paper-ta-pareto-2d.toml"));
  IraceScenarioOptions o;
  o.out_dir = scratch("pareto").string();
  EXPECT_THROW(write_irace_scenario(c, o), sim::ConfigError);  // two objectives, irace minimises one cost
  c = tiny();
  c.budget = Budget{0, 0, 60.0};
  try {
    write_irace_scenario(c, o);
    FAIL() << "a wall-time budget has no simulation count";
  } catch (const sim::ConfigError& e) {
    EXPECT_EQ(e.key(), "budget");
  }
  EXPECT_THROW(read_irace_manifest(scratch("empty").string()), sim::ConfigError);
}

TEST(IraceImport, ElitesBecomeParamsWithProvenance) {
  const EvolveConfig c = tiny();
  const auto dir = scratch("import");
  const auto csv = dir / "elites.csv";
  write_text(csv,
             "rank,id,T_explore0,p_turn,mean_cost,runs,experiments,irace_version,irace_seed\n"
             "1,12,761,0.0029166,0.904969264218544,8,96,3.5.6863679,3\n"
             "2,4,315,0.0127214,0.892622006164417,8,96,3.5.6863679,3\n");
  const std::vector<IraceElite> e = read_irace_elites(csv.string());
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].id, "12");
  EXPECT_EQ(e[0].mean_cost, 0.904969264218544);
  EXPECT_EQ(e[1].values, (std::vector<std::pair<std::string, std::string>>{{"T_explore0", "315"},
                                                                           {"p_turn", "0.0127214"}}));
  const Decoded d = irace_elite_candidate(c.genome, e[0], csv.string());
  EXPECT_EQ(d.params.t_explore0, 750.0);
  EXPECT_EQ(d.params.p_turn, 0.0029166);
  IraceManifest m;
  m.config = "/x/tiny_tune.toml";
  m.config_hash = config_hash(c);
  m.max_experiments = 102;
  const std::string toml = irace_params_toml(c, m, e[0], d, dir.string());
  EXPECT_EQ(
      toml.rfind("# irace 3.5.6863679: elite 1 (configuration 12, mean cost 0.904969264218544 over 8", 0),
      0u);
  EXPECT_NE(toml.find(config_hash(c)), std::string::npos);
  const sim::Params back = sim::parse_params(toml, "best.toml");
  EXPECT_EQ(back.t_explore0, 750.0);
  EXPECT_EQ(back.p_turn, 0.0029166);
}

TEST(IraceImport, MalformedElitesNameFileLineAndColumn) {
  const EvolveConfig c = tiny();
  const auto dir = scratch("bad");
  const auto csv = dir / "elites.csv";
  write_text(csv,
             "rank,id,T_explore0,mean_cost,runs,experiments,irace_version,irace_seed\n1,3,x,0.5,2,9,3.5,1\n");
  const std::vector<IraceElite> e = read_irace_elites(csv.string());  // values are read as text
  try {
    irace_elite_candidate(c.genome, e[0], csv.string());
    FAIL() << "T_explore0 = x";
  } catch (const sim::ConfigError& err) {
    EXPECT_EQ(err.key(), "T_explore0");
  }
  write_text(
      csv, "rank,id,T_explore0,mean_cost,runs,experiments,irace_version,irace_seed\n1,3,800,0.5,2,9,3.5,1\n");
  try {
    irace_elite_candidate(c.genome, read_irace_elites(csv.string())[0], csv.string());
    FAIL() << "p_turn is missing";
  } catch (const sim::ConfigError& err) {
    EXPECT_EQ(err.key(), "p_turn");
  }
  write_text(csv, "rank,id,mean_cost\n1,3,0.5\n");
  try {
    read_irace_elites(csv.string());
    FAIL() << "columns missing";
  } catch (const sim::ConfigError& err) {
    EXPECT_EQ(err.line(), 1);
    EXPECT_EQ(err.key(), "runs");
  }
  write_text(
      csv,
      "rank,id,T_explore0,mean_cost,runs,experiments,irace_version,irace_seed\n1,3,800,cheap,2,9,3.5,1\n");
  try {
    read_irace_elites(csv.string());
    FAIL() << "a cost that is no number";
  } catch (const sim::ConfigError& err) {
    EXPECT_EQ(err.line(), 2);
    EXPECT_EQ(err.key(), "mean_cost");
  }
}

}  // namespace
}  // namespace swarmpath::evolve
