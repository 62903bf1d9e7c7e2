// SPDX-License-Identifier: MIT
// Shipped genomes stay true: the manifest lists every tuned genome with its config and run, each
// genome holds the values its run chose, and verification runs a genome and the default on
// fresh cases (seeds and arenas no evolve run draws) and judges as the run did.
#include "evolve/verify.hpp"

#include <filesystem>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evolve/genome_manifest.hpp"
#include "evolve/seeds.hpp"
#include "evolve_test_support.hpp"
#include "sim/params.hpp"

namespace swarmpath::evolve {
namespace {

namespace fs = std::filesystem;

TEST(Verify, VerificationCasesAreFreshSeedsAndArenas) {
  const std::vector<EvalSetting> settings = {{"s", 8, false}, {"h", 8, true}, {"open", 8, false, 0, 2, 2, 4}};
  const std::vector<EvalCase> v = verification_cases(settings, 3, 5, 7);
  ASSERT_EQ(v.size(), 3u + 3u + 5u * 2u);  // held-out settings too; arenas x the entry's seeds
  std::set<std::uint64_t> used;
  for (std::int64_t g = 0; g < 20; ++g) {
    for (const EvalCase& c : generation_cases(settings, 3, 7, g, false)) used.insert(c.seed);
  }
  for (const EvalCase& c : reevaluation_cases(settings, 3, 7)) used.insert(c.seed);
  for (const EvalCase& c : v) {
    EXPECT_EQ(used.count(c.seed), 0u);
    if (c.arena >= 0) {
      EXPECT_EQ(arena_use(c.arena_seed), ArenaUse::kVerify);
    }
  }
  EXPECT_NE(verification_cases(settings, 3, 5, 7, 1)[0].seed, v[0].seed);  // another salt, other seeds
}

TEST(Verify, TheBetterGenomeWinsAndTheWorseDoesNot) {
  const EvolveConfig c = testing::tiny("random", 1);
  const testing::FakeObjective f({{"s", 8, false}}, [](const sim::Params& p, const EvalCase& k) {
    return p.w_away + 0.001 * static_cast<double>(k.seed % 5);
  });
  sim::Params good = c.genome.base, bad = c.genome.base;
  good.w_away = 0.1;
  bad.w_away = 0.9;
  ThreadPool pool(2);
  const VerifyResult w = verify_genome(c, f, good, bad, 4, 2, 0, pool);
  EXPECT_TRUE(w.wins) << w.verdict;
  EXPECT_NEAR(w.fitness_difference.mean, -0.8, 1e-12);
  EXPECT_EQ(w.genome.runs, 4);
  const VerifyResult l = verify_genome(c, f, bad, good, 4, 2, 0, pool);
  EXPECT_FALSE(l.wins);
  EXPECT_NE(l.verdict.find("no longer wins"), std::string::npos) << l.verdict;
}

TEST(Verify, EveryShippedEvolveConfigLoads) {
  for (const auto& e : fs::directory_iterator(testing::source("configs/evolve"))) {
    EXPECT_NO_THROW(load_evolve_config(e.path().string())) << e.path();
  }
}

TEST(Verify, EveryShippedTunedGenomeIsListedAndHoldsWhatItsRunChose) {
  const GenomeManifest m = load_genome_manifest(testing::source("genomes/tuned.toml"));
  std::set<std::string> listed;
  for (const ShippedGenome& g : m.genomes) {
    listed.insert(fs::path(g.params).filename().string());
    EXPECT_EQ(genome_mismatch(g), "") << g.params;
    EXPECT_NO_THROW(load_evolve_config(g.config)) << g.config;
    EXPECT_EQ(fs::path(g.config).parent_path().filename(), "evolve") << "configs/evolve/ holds the config";
    EXPECT_EQ(fs::path(g.run).parent_path(), fs::path(g.params).parent_path())
        << "run.json beside the genome";
  }
  // a genome written by evolve (its first line says so) must be in the manifest
  for (const auto& e : fs::directory_iterator(testing::source("genomes"))) {
    if (e.path().extension() != ".toml") continue;
    const std::string text = testing::read_text(e.path());
    if (text.rfind("# swarmpath evolve", 0) == 0) {
      EXPECT_EQ(listed.count(e.path().filename().string()), 1u)
          << e.path() << " is not in genomes/tuned.toml";
    }
  }
  // a genome whose tuned value was edited after its run is caught (the first value its run tuned)
  const fs::path dir = testing::scratch("edited");
  ShippedGenome g = m.genomes.front();
  const nlohmann::json run = nlohmann::json::parse(testing::read_text(g.run));
  const std::string key = run.at("best").at("tuned").begin().key();
  std::string text = testing::read_text(g.params);
  const auto at = text.find("\n" + key + " = ");
  ASSERT_NE(at, std::string::npos) << key;
  const sim::ParamInfo* info = sim::find_param(key);
  ASSERT_NE(info, nullptr) << key;
  const double edited = run["best"]["tuned"][key].get<double>() == info->lo ? info->hi : info->lo;
  text.replace(at, text.find('\n', at + 1) - at, "\n" + key + " = " + std::to_string(edited));
  testing::write_text(dir / "g.toml", text);
  g.params = (dir / "g.toml").string();
  EXPECT_NE(genome_mismatch(g).find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace swarmpath::evolve
