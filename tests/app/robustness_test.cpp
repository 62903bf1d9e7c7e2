// SPDX-License-Identifier: MIT
// The robustness sweep's bookkeeping: which runs it makes, and how the cells and the 10-point
// target are computed from them.
#include "app/robustness.hpp"

#include <sstream>

#include <gtest/gtest.h>

#include "app/robustness_output.hpp"

namespace swarmpath::app {
namespace {

sim::Scenario arena(const std::string& name) {
  sim::Scenario s;
  s.name = name;
  return s;
}

TEST(Robustness, PathFormationRunsOncePerFailureFraction) {
  const RobustnessGrid g{{0.0, 0.1}, {0.0, 0.1, 0.3}};
  const auto variants = make_variants(2, g);
  ASSERT_EQ(variants.size(), 2u * 2u * 3u);
  const auto cases =
      robustness_cases(variants, {60, 100}, {sim::Mode::kPathFormation, sim::Mode::kTaskAllocation}, 3, 7);
  int pf = 0, ta = 0;
  for (const GridCase& c : cases) {
    if (c.mode == sim::Mode::kPathFormation) {
      ++pf;
      EXPECT_EQ(variants[c.scenario].loss, 0u);
    } else {
      ++ta;
    }
    EXPECT_GE(c.seed, 7u);
    EXPECT_LE(c.seed, 9u);
  }
  EXPECT_EQ(pf, 2 * 2 * 2 * 3);      // scenarios x fractions x robots x seeds
  EXPECT_EQ(ta, 2 * 2 * 3 * 2 * 3);  // ... x packet losses
  // each variant carries its condition in its fault model
  const auto scenarios = variant_scenarios({arena("a"), arena("b")}, variants, g);
  EXPECT_DOUBLE_EQ(scenarios[5].faults.fail_fraction, 0.1);  // a, failing 10 %, packet loss 30 %
  EXPECT_DOUBLE_EQ(scenarios[5].faults.packet_loss, 0.3);
  EXPECT_EQ(scenarios[6].name, "b");
}

TEST(Robustness, PathFormationThatTellsSightingsRunsAtEveryPacketLoss) {
  // with share_sighting path formation listens to the medium: a packet loss is a condition for it
  RobustnessGrid g{{0.0, 0.1}, {0.0, 0.3}};
  g.pf_radio = true;
  EXPECT_TRUE(uses_radio(sim::Mode::kPathFormation, g));
  EXPECT_FALSE(uses_radio(sim::Mode::kPathFormation, RobustnessGrid{}));
  const auto variants = make_variants(1, g);
  const std::vector<sim::Mode> modes{sim::Mode::kPathFormation};
  const auto cases = robustness_cases(variants, {10}, modes, 2, 1, g.pf_radio);
  ASSERT_EQ(cases.size(), 2u * 2u * 2u);  // fractions x losses x seeds
  std::vector<GridRun> runs;
  for (const GridCase& c : cases) {
    sim::Metrics m;
    m.success = variants[c.scenario].loss == 0;  // the loss costs every success
    m.ticks_to_form = m.success ? 1000 : -1;
    m.path_length_tu = 100.0;
    runs.push_back({c, m});
  }
  const RobustnessReport r = summarise_robustness({arena("a")}, {100.0}, variants, g, modes, runs);
  EXPECT_DOUBLE_EQ(r.at(sim::Mode::kPathFormation, 0, 0).success_pct, 100.0);
  EXPECT_DOUBLE_EQ(r.at(sim::Mode::kPathFormation, 0, 1).success_pct, 0.0);  // not the loss-0 runs
  std::ostringstream md;
  write_robustness_markdown(md, r);
  EXPECT_NE(md.str().find("| pf | 30 % |"), std::string::npos) << md.str();
  EXPECT_EQ(md.str().find("any (no radio)"), std::string::npos) << md.str();
}

TEST(Robustness, CellsAndTheDropAtTenPercent) {
  const RobustnessGrid g{{0.0, 0.1}, {0.0, 0.5}};
  const std::vector<sim::Scenario> base{arena("a")};
  const auto variants = make_variants(1, g);
  const std::vector<sim::Mode> modes{sim::Mode::kPathFormation, sim::Mode::kTaskAllocation};
  const auto cases = robustness_cases(variants, {10}, modes, 4, 1);
  std::vector<GridRun> runs;
  for (const GridCase& c : cases) {
    sim::Metrics m;
    const Variant& v = variants[c.scenario];
    // pf: 4/4 without failures, 3/4 with; ta: 4/4, 2/4 with, and the loss costs one more success
    const int successes = c.mode == sim::Mode::kPathFormation
                              ? (v.fail == 0 ? 4 : 3)
                              : (v.fail == 0 ? 4 : 2) - static_cast<int>(v.loss);
    m.success = static_cast<int>(c.seed) <= successes;
    m.ticks_to_form = m.success ? 1000 * static_cast<std::int64_t>(c.seed) : -1;
    m.path_length_tu = 110.0;
    m.failures = v.fail == 0 ? 0 : 1;
    runs.push_back({c, m});
  }
  const RobustnessReport r = summarise_robustness(base, {100.0}, variants, g, modes, runs);
  const RobustnessCell& pf = r.at(sim::Mode::kPathFormation, 1, 1);  // a pf run stands for every loss
  EXPECT_EQ(pf.runs, 4);
  EXPECT_DOUBLE_EQ(pf.success_pct, 75.0);
  EXPECT_DOUBLE_EQ(pf.ticks_to_form, 2000.0);  // seeds 1-3 succeed
  EXPECT_DOUBLE_EQ(pf.ratio_to_astar, 1.1);
  EXPECT_DOUBLE_EQ(pf.failures, 1.0);
  EXPECT_DOUBLE_EQ(r.at(sim::Mode::kTaskAllocation, 1, 1).success_pct, 25.0);
  EXPECT_DOUBLE_EQ(*success_drop_at_10pct(r, sim::Mode::kPathFormation), 25.0);
  EXPECT_DOUBLE_EQ(*success_drop_at_10pct(r, sim::Mode::kTaskAllocation), 50.0);
  EXPECT_EQ(r.per_scenario.size(), 2u * 2u * 2u);
}

}  // namespace
}  // namespace swarmpath::app
