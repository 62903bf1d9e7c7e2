// SPDX-License-Identifier: MIT
// The parameter table (SPEC §7) and params files.
#include "sim/params.hpp"

#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "sim/config_error.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

TEST(Params, TableHoldsSpecRows1To42InOrderWithTheirDefaults) {
  const auto table = param_table();
  int row = 0;
  const Params defaults;
  for (const ParamInfo& info : table) {
    if (info.row == 0) continue;  // options outside SPEC §7
    EXPECT_EQ(info.row, ++row) << info.name;
    EXPECT_EQ(get_value(defaults, info), info.def) << info.name;
    EXPECT_LE(info.lo, info.def) << info.name;
    EXPECT_GE(info.hi, info.def) << info.name;
    EXPECT_GT(info.step, 0.0) << info.name;
  }
  EXPECT_EQ(row, 42);
  EXPECT_TRUE(check_params(defaults).empty()) << check_params(defaults);
}

// the options outside SPEC §7 too: each default is written twice (params.hpp and the table)
TEST(Params, TableDefaultOfEveryKeyIsTheStructsDefault) {
  const Params defaults;
  for (const ParamInfo& info : param_table()) EXPECT_EQ(get_value(defaults, info), info.def) << info.name;
}

// every option beyond SPEC §7 says which SPEC rule it changes; SPEC's own rows need not
TEST(Params, EveryOptionOutsideSpecSevenNamesTheRuleItChanges) {
  for (const ParamInfo& info : param_table()) {
    if (info.row == 0) {
      EXPECT_EQ(info.rule.substr(0, 2), "§") << info.name << ": \"" << info.rule << "\"";
      EXPECT_FALSE(info.meaning.empty()) << info.name;
    } else {
      EXPECT_TRUE(info.rule.empty()) << info.name;
    }
  }
}

TEST(Params, PaperThresholdsAreThePapersValues) {  // paper, "Subgoal Formation": 30, 70, 100, 20
  const Params p;
  EXPECT_EQ(p.d_detect, 30);
  EXPECT_EQ(p.d_sub, 70);
  EXPECT_EQ(p.r_vis, 100);
  EXPECT_EQ(p.r_rec, 20);
  EXPECT_EQ(find_param("d_detect")->fixed, "P");
  EXPECT_EQ(find_param("R_vis")->fixed, "P/H");
}

TEST(Params, FileSetsValuesAndKeepsDefaultsForTheRest) {
  const Params p =
      parse_params("v_max = 12.5\nT_lost = 4\nrevert_orphans = true\nt_source = \"elapsed\"\n", "p.toml");
  EXPECT_EQ(p.v_max, 12.5);
  EXPECT_EQ(p.t_lost, 4);
  EXPECT_TRUE(p.revert_orphans);
  EXPECT_EQ(p.t_source, TSource::kElapsed);
  EXPECT_EQ(p.d_sub, 70);  // untouched
}

TEST(Params, TextOnTopOfABaseKeepsTheBaseForTheRest) {
  Params base;
  base.v_max = 12.5;
  base.theta_hard = 80;
  const Params p = parse_params("T_lost = 4\n", "replace", base);
  EXPECT_EQ(p.t_lost, 4);
  EXPECT_EQ(p.v_max, 12.5);  // the base's, not the default
  // the cross constraints are checked on the result: theta_soft 75 <= the base's theta_hard 80
  EXPECT_EQ(parse_params("theta_soft = 75\n", "replace", base).theta_soft, 75);
  try {
    parse_params("theta_soft = 85\n", "replace", base);
    ADD_FAILURE() << "theta_soft 85 > theta_hard 80 accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "theta_soft") << e.what();
  }
}

TEST(Params, WriteThenReadGivesTheSameValues) {
  Params p;
  p.v_max = 17.5;
  p.kappa = 2.05;
  p.early_stop_in_rec = false;
  p.neighbour_id = NeighbourId::kVisionOnly;
  std::ostringstream text;
  write_params_toml(text, p, "# test\n");
  const Params q = parse_params(text.str(), "roundtrip.toml");
  for (const ParamInfo& info : param_table()) EXPECT_EQ(get_value(p, info), get_value(q, info)) << info.name;
}

void expect_rejected(const std::string& text, int line, const std::string& key, const std::string& fragment) {
  try {
    parse_params(text, "p.toml");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ParamsRejects, UnknownNameWithSuggestion) {
  expect_rejected("v_max = 10\nd_detec = 30\n", 2, "d_detec", "did you mean 'd_detect'");
}

TEST(ParamsRejects, RemovedSwitchIsNamedAsRemoved) {
  expect_rejected("v_max = 10\nalign_taper = true\n", 2, "align_taper", "was removed from the controller");
  expect_rejected("T_nudge = 100\n", 1, "T_nudge", "delete this line");
  expect_rejected("spot_patience = 300\n", 1, "spot_patience", "showed nothing on the training arenas");
}

TEST(ParamsRejects, ValueOutsideItsRange) {
  expect_rejected("\nd_sub = 120\n", 2, "d_sub", "outside its range [40, 95]");
  expect_rejected("T_lost = 2.5\n", 1, "T_lost", "expected an integer");
  expect_rejected("early_stop_in_rec = \"yes\"\n", 1, "early_stop_in_rec", "expected a boolean");
  expect_rejected("t_source = \"clock\"\n", 1, "t_source", "must be \"budget\" or \"elapsed\"");
}

TEST(ParamsRejects, CrossConstraints) {
  expect_rejected("theta_soft = 80\ntheta_hard = 70\n", 1, "theta_soft", "must be <= theta_hard");
  expect_rejected("R_vis = 80\nR_keep = 85\n", 2, "R_keep", "must be <= R_vis");
}

TEST(Params, DefaultGenomeFileHoldsTheCodesDefaults) {
  const Params p = load_params(test::source_path("genomes/default.toml"));
  const Params defaults;
  for (const ParamInfo& info : param_table())
    EXPECT_EQ(get_value(p, info), get_value(defaults, info)) << info.name;
}

// the speed study (docs/CHOICES.md, "Speed and the allocation count"): genomes/paper-v10.toml is the default
// genome at SPEC's assumed 10 cm/s, with the trail back-off that was measured at that speed
TEST(Params, TenCmPerSecondGenomeDiffersFromTheDefaultOnlyInSpeedAndBackOff) {
  const Params paper = load_params(test::source_path("genomes/default.toml"));
  const Params slow = load_params(test::source_path("genomes/paper-v10.toml"));
  EXPECT_EQ(paper.v_max, 20.0);
  EXPECT_EQ(slow.v_max, 10.0);
  EXPECT_TRUE(paper.backoff_far_spot);
  EXPECT_FALSE(slow.backoff_far_spot);
  for (const ParamInfo& info : param_table()) {
    const std::string name(info.name);
    if (name == "v_max" || name == "backoff_far_spot") continue;
    EXPECT_EQ(get_value(slow, info), get_value(paper, info)) << info.name;
  }
}

// docs/CHOICES.md, "Speed and the allocation count": genomes/paper-single.toml is the default genome with the
// paper's single allocation: delta 25 / 35 / 35, slower recruiting (T_starve 600, T_recruit 300), and no
// second allocation of a chain's end that ran out
TEST(Params, SingleAllocationGenomeDiffersFromTheDefaultOnlyInTheAllocationAndRecruiting) {
  const Params paper = load_params(test::source_path("genomes/default.toml"));
  const Params single = load_params(test::source_path("genomes/paper-single.toml"));
  EXPECT_EQ(paper.delta_open + paper.delta_obstacle + paper.delta_complex, 0.0);
  EXPECT_EQ(single.delta_open, 25.0);
  EXPECT_EQ(single.delta_obstacle, 35.0);
  EXPECT_EQ(single.delta_complex, 35.0);
  EXPECT_LT(paper.t_starve, single.t_starve);
  EXPECT_LT(paper.t_recruit, single.t_recruit);
  EXPECT_TRUE(paper.refound_starved);
  EXPECT_FALSE(single.refound_starved);
  for (const ParamInfo& info : param_table()) {
    const std::string name(info.name);
    if (name.rfind("delta_", 0) == 0 || name == "T_starve" || name == "T_recruit" ||
        name == "refound_starved")
      continue;
    EXPECT_EQ(get_value(single, info), get_value(paper, info)) << info.name;
  }
}

// the allocation study (docs/CHOICES.md, "Speed and the allocation count"): genomes/paper-frugal.toml
// is the single-allocation genome with t from the founder's trip and delta calibrated for it, and
// resting robots recruited as quickly as in genomes/default.toml
TEST(Params, FrugalGenomeDiffersFromTheSingleAllocationGenomeOnlyInTheAllocationAndRecruiting) {
  const Params paper = load_params(test::source_path("genomes/default.toml"));
  const Params single = load_params(test::source_path("genomes/paper-single.toml"));
  const Params frugal = load_params(test::source_path("genomes/paper-frugal.toml"));
  EXPECT_EQ(single.t_source, TSource::kBudget);
  EXPECT_EQ(frugal.t_source, TSource::kElapsed);
  EXPECT_LT(frugal.delta_open, single.delta_open);
  EXPECT_LT(frugal.delta_obstacle, single.delta_obstacle);
  EXPECT_LT(frugal.delta_complex, single.delta_complex);
  EXPECT_EQ(frugal.t_starve, paper.t_starve);
  EXPECT_EQ(frugal.t_recruit, paper.t_recruit);
  EXPECT_FALSE(frugal.refound_starved);
  for (const ParamInfo& info : param_table()) {
    const std::string name(info.name);
    if (name == "t_source" || name.rfind("delta_", 0) == 0 || name == "T_starve" || name == "T_recruit")
      continue;
    EXPECT_EQ(get_value(frugal, info), get_value(single, info)) << info.name;
  }
}

}  // namespace
}  // namespace swarmpath::sim
