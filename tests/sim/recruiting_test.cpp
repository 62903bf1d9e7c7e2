// SPDX-License-Identifier: MIT
// A chain that ran out of robots (task allocation): its end is completed by a resting robot that
// sees it (rest_recruit, T10), by one that hears its call (recruit_call, T10), or, beyond the call's
// reach, by the robots the end fetches from the nest (refound_starved, T11-T12). Each mechanism in
// tests/data/chain_end.toml, set up by hand: a chain of RED subgoals from the goal, resting robots at
// their deployment points by the nest, and no other robot that could close the chain.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

Scenario corridor() { return load_scenario(test::source_path("tests/data/chain_end.toml")); }

// the chain's robots along y = 0, from the goal (x = 4) toward the nest, 65 cm apart, its end at
// `end_x`; then resting robots at (-3.3, 0), (-3.5, +-0.35), (-3.8, 0), (-4.1, +-0.35), (-4.4, 0)
struct ChainEnd {
  Scenario s = corridor();
  std::vector<Pose> poses;
  int chain = 0;

  explicit ChainEnd(double end_x) {
    // (facing the nest: a robot facing exactly away from where it drives has D + F = 0, SPEC §2.1)
    for (double x = 3.35; x >= end_x - 1e-9; x -= 0.65) poses.push_back({{x, 0.0}, -1.0, 0.0});
    chain = static_cast<int>(poses.size());
    for (const Vec2 q : {Vec2{-3.3, 0.0}, Vec2{-3.5, 0.35}, Vec2{-3.5, -0.35}, Vec2{-3.8, 0.0},
                         Vec2{-4.1, 0.35}, Vec2{-4.1, -0.35}, Vec2{-4.4, 0.0}})
      poses.push_back({q, -1.0, 0.0});
  }

  // the world set up as described: chain robot k names robot k - 1 (the first, the goal) as its parent
  World world(const Params& p) const {
    World w = make_world(s, p, Mode::kTaskAllocation, 1, poses);
    for (int k = 0; k < robot_count(w); ++k) {
      RobotMemory& m = w.memory[static_cast<std::size_t>(k)];
      if (k < chain) {
        m.ta.state = TaState::kPathFormation;
        m.pf.role = PfRole::kAllocated;
        m.pf.state = PfState::kSubgoal;
        m.pf.parent.id = k == 0 ? kGoalEmitter : k - 1;
        m.pf.parent.last_seen = k == 0 ? s.goal : poses[static_cast<std::size_t>(k - 1)].p;
        m.pf.parent.visible = true;
        w.leds[static_cast<std::size_t>(k)] = Led::kRed;
        w.tags[static_cast<std::size_t>(k)] = m.pf.parent.id;
      } else {
        m.ta.state = TaState::kRestingTask;
        m.ta.arrived = true;
        w.leds[static_cast<std::size_t>(k)] = Led::kBlack;
      }
    }
    return w;
  }

  static int robot_count(const World& w) { return static_cast<int>(w.memory.size()); }

  // the run to the formed path (or max_ticks); `refounders`: robots that went home to fetch robots (T12)
  Metrics run(const Params& p, int* refounders = nullptr) const {
    World w = world(p);
    MetricsAccumulator acc;
    acc.begin(robot_count(w));
    std::vector<bool> refounded(w.memory.size(), false);
    while (w.tick < s.sim.max_ticks && !acc.complete()) {
      step(s, p, w, acc);
      for (std::size_t i = 0; i < w.memory.size(); ++i)
        refounded[i] = refounded[i] || w.memory[i].ta.refounder;
    }
    if (refounders != nullptr)
      *refounders = static_cast<int>(std::count(refounded.begin(), refounded.end(), true));
    return acc.finish(w.tick, s.sim.dt(), state_hash(w));
  }
};

// each mechanism alone: the others off
Params only(bool rest_recruit, bool recruit_call, bool refound) {
  Params p;
  p.rest_recruit = rest_recruit;
  p.recruit_call = recruit_call;
  p.refound_starved = refound;
  p.t_refound = 300;
  return p;
}

TEST(ChainEnd, ARestingRobotThatSeesTheEndFormsTheLastLink) {  // T10, rest_recruit
  const ChainEnd c(-2.5);  // 1.5 m from the nest, 0.8 m from the nearest resting robot
  const Metrics without = c.run(only(false, false, false));
  EXPECT_FALSE(without.success) << "formed without any recruit in " << without.ticks << " ticks";
  const Metrics with = c.run(only(true, false, false));
  EXPECT_TRUE(with.success) << "no path in " << with.ticks << " ticks";
  EXPECT_GE(with.recruited, 1);
  EXPECT_LE(with.recruited, 2);  // the link it lacked, not the resting crowd
}

TEST(ChainEnd, AnEndOutOfViewCallsTheRestingRobotsOnTheMedium) {  // T10, recruit_call
  const ChainEnd c(-1.2);  // 2.1 m from the nearest resting robot: out of its 1 m view, within 3 m
  const Metrics seen_only = c.run(only(true, false, false));
  EXPECT_FALSE(seen_only.success) << "formed without a call in " << seen_only.ticks << " ticks";
  EXPECT_EQ(seen_only.recruited, 0);
  const Metrics called = c.run(only(true, true, false));
  EXPECT_TRUE(called.success) << "no path in " << called.ticks << " ticks";
  EXPECT_GE(called.recruited, 2);  // the links from -1.2 m to the nest's view
  EXPECT_LE(called.recruited, 5);
}

TEST(ChainEnd, AnEndBeyondTheCallFetchesRobotsFromTheNest) {  // T11, T12, refound_starved
  const ChainEnd c(0.1);  // 3.4 m from the nearest resting robot: beyond the medium's 3 m
  const Metrics calling = c.run(only(true, true, false));
  EXPECT_FALSE(calling.success) << "formed without refounding in " << calling.ticks << " ticks";
  EXPECT_EQ(calling.recruited, 0);
  int refounders = 0;
  const Metrics fetched = c.run(only(true, true, true), &refounders);
  EXPECT_TRUE(fetched.success) << "no path in " << fetched.ticks << " ticks";
  EXPECT_GE(refounders, 1);
  EXPECT_GT(fetched.allocated, calling.allocated);  // the robots the end allocated from the resting ones
}

}  // namespace
}  // namespace swarmpath::sim
