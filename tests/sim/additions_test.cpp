// SPDX-License-Identifier: MIT
// The additions beyond SPEC's rules: each has a switch, the default runs them all, and the
// paper-literal params switch every one off and keep SPEC §7's defaults.
#include "sim/additions.hpp"

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

TEST(Additions, EachIsOnByDefaultOrUnderTrialAndHasASwitchWithItsSpecRule) {
  const Params defaults;
  std::set<std::string_view> names;
  for (const Addition& a : additions()) {
    EXPECT_TRUE(names.insert(a.name).second) << "twice: " << a.name;
    EXPECT_EQ(is_on(defaults, a), in_default(a)) << a.name;  // on, or registered under trial
    EXPECT_FALSE(a.rule.empty()) << a.name;
    for (const Setting& s : a.off) {
      if (s.key.empty()) continue;
      const ParamInfo* info = find_param(s.key);
      ASSERT_NE(info, nullptr) << a.name << ": " << s.key;
      EXPECT_EQ(info->row, 0) << s.key << " is a SPEC §7 row, not an addition";
      EXPECT_FALSE(info->rule.empty()) << s.key << " names no SPEC rule";
      EXPECT_GE(s.value, info->lo) << s.key;  // the off value is a value the key accepts
      EXPECT_LE(s.value, info->hi) << s.key;
    }
    for (const std::string_view need : a.needs) {
      if (need.empty()) continue;
      EXPECT_NE(find_addition(need), nullptr) << a.name << " needs " << need;
    }
  }
}

TEST(Additions, SwitchingOneOffChangesOnlyItsOwnKeys) {
  for (const Addition& a : additions()) {
    const Params defaults;
    Params p = defaults;
    switch_off(p, a);
    EXPECT_FALSE(is_on(p, a)) << a.name;
    for (const ParamInfo& info : param_table()) {
      bool own = false;
      for (const Setting& s : a.off) own = own || s.key == info.name;
      if (own) continue;
      EXPECT_EQ(get_value(p, info), get_value(defaults, info)) << a.name << " changed " << info.name;
    }
  }
}

// a true-by-default switch outside SPEC §7 is an addition, so that paper-literal switches it off
TEST(Additions, EveryOptionOnByDefaultIsRegistered) {
  const Params defaults;
  std::set<std::string_view> keys;
  for (const Addition& a : additions()) {
    for (const Setting& s : a.off) keys.insert(s.key);
  }
  for (const ParamInfo& info : param_table()) {
    if (info.row != 0 || info.type != ParamType::kBool || get_value(defaults, info) == 0.0) continue;
    EXPECT_TRUE(keys.contains(info.name)) << info.name << " is on by default but is no addition";
  }
}

TEST(Additions, PaperLiteralSwitchesEveryOneOffAndKeepsSpecDefaults) {
  const Params p = paper_literal();
  for (const Addition& a : additions()) EXPECT_FALSE(is_on(p, a)) << a.name;
  // SPEC §7 rows 7 and 33-35: v_max 10 cm/s [A], delta 5 / 15 / 20
  EXPECT_EQ(p.v_max, 10);
  EXPECT_EQ(p.delta_open, 5);
  EXPECT_EQ(p.delta_obstacle, 15);
  EXPECT_EQ(p.delta_complex, 20);
  const Params defaults;
  for (const ParamInfo& info : param_table()) {
    if (info.row == 0 || spec_default(info.name) != nullptr) continue;
    EXPECT_EQ(get_value(p, info), get_value(defaults, info)) << info.name;  // the other rows: SPEC's
  }
  EXPECT_FALSE(p.backoff_spot || p.form_one_at_a_time || p.chain_bypass);  // options off by default
  EXPECT_TRUE(check_params(p).empty()) << check_params(p);
}

// genomes/paper-literal.toml is SPEC's controller, every key written out
TEST(Additions, PaperLiteralGenomeFileHoldsPaperLiteral) {
  const Params file = load_params(test::source_path("genomes/paper-literal.toml"));
  const Params literal = paper_literal();
  for (const ParamInfo& info : param_table())
    EXPECT_EQ(get_value(file, info), get_value(literal, info)) << info.name;
  EXPECT_EQ(controller_name(file), "paper-literal");
  EXPECT_EQ(controller_name(load_params(test::source_path("genomes/default.toml"))), "default");
  Params custom;
  custom.w_seek = 0;
  EXPECT_EQ(controller_name(custom), "custom");
  int in_the_default = 0;
  for (const Addition& a : additions()) in_the_default += in_default(a) ? 1 : 0;
  EXPECT_EQ(additions_on(custom), in_the_default - 1);
  EXPECT_EQ(additions_on(literal), 0);
}

TEST(Additions, SwitchingOneOnInPaperLiteralSwitchesOnWhatItNeeds) {
  for (const Addition& a : additions()) {
    Params p = paper_literal();
    switch_on(p, a);
    EXPECT_TRUE(is_on(p, a)) << a.name;
    for (const std::string_view need : a.needs) {
      if (need.empty()) continue;
      EXPECT_TRUE(is_on(p, *find_addition(need))) << a.name << " without " << need;
    }
    EXPECT_TRUE(check_params(p).empty()) << a.name << ": " << check_params(p);
  }
  Params p = paper_literal();
  switch_on(p, *find_addition("refound_starved"));  // needs recruit_call, which needs rest_recruit
  EXPECT_TRUE(p.refound_starved && p.recruit_call && p.rest_recruit && p.single_child);
  EXPECT_FALSE(p.guided_departure);
}

}  // namespace
}  // namespace swarmpath::sim
