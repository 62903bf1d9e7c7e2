// SPDX-License-Identifier: MIT
// Determinism as a tested feature (Box2D's habit): a golden state_hash, equal results on
// repeated runs, and equal results when many threads simulate at once.
// Golden values belong to one toolchain: Debian bookworm, g++ 12, libbox2d 2.4.1.
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "sim/hash.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

Scenario golden_scenario() { return with_max_ticks(with_robots(load_scenario(test::paper_env(4)), 30), 600); }

TEST(Determinism, GoldenHashDiffusionEnv4) {
  // update only with a reason, stated in the commit that changes it
  constexpr std::uint64_t kExpected = 0xca3efe7384181d4cULL;
  const Metrics m = evaluate(Params{}, golden_scenario(), Mode::kDiffusion, 42);
  EXPECT_EQ(m.ticks, 600);
  EXPECT_EQ(m.state_hash, kExpected) << "actual state_hash 0x" << to_hex(m.state_hash);
}

TEST(Determinism, SameInputsSameRun) {
  const Scenario s = golden_scenario();
  const Metrics a = evaluate(Params{}, s, Mode::kDiffusion, 7);
  const Metrics b = evaluate(Params{}, s, Mode::kDiffusion, 7);
  const Metrics c = evaluate(Params{}, s, Mode::kDiffusion, 8);
  EXPECT_EQ(a.state_hash, b.state_hash);
  EXPECT_EQ(a.distance_m, b.distance_m);
  EXPECT_NE(a.state_hash, c.state_hash);
}

TEST(Determinism, ThreadsRunningAtOnceGiveTheSameHashes) {
  const Scenario s = golden_scenario();
  constexpr int kThreads = 6;
  std::uint64_t sequential[kThreads];
  for (int i = 0; i < kThreads; ++i)
    sequential[i] = evaluate(Params{}, s, Mode::kDiffusion, 100 + i % 3).state_hash;
  std::uint64_t parallel[kThreads] = {};
  std::vector<std::thread> pool;
  for (int i = 0; i < kThreads; ++i) {
    pool.emplace_back(
        [&, i] { parallel[i] = evaluate(Params{}, s, Mode::kDiffusion, 100 + i % 3).state_hash; });
  }
  for (auto& t : pool) t.join();
  for (int i = 0; i < kThreads; ++i) EXPECT_EQ(parallel[i], sequential[i]) << "thread " << i;
}

TEST(Determinism, StepSensesAndControlsRobotByRobotAsThePhasesWould) {
  // step() fuses sensing and control per robot; the phases one after the other must give the
  // same run. Task allocation reads every sensor (proximity, camera with tags, RAB).
  const Scenario s = with_robots(load_scenario(test::paper_env(1)), 40);
  const Params p;
  World fused = make_world(s, p, Mode::kTaskAllocation, 5);
  World phased = make_world(s, p, Mode::kTaskAllocation, 5);
  MetricsAccumulator mf;
  MetricsAccumulator mp;
  mf.begin(fused.robot_count());
  mp.begin(phased.robot_count());
  for (int t = 1; t <= 3000; ++t) {
    step(s, p, fused, mf);
    sense_all(s, p, phased);
    control_all(p, phased);
    act_all(phased);
    integrate(s, phased, mp);
    mp.observe(s, phased);
    if (t % 100 == 0) {
      ASSERT_EQ(state_hash(fused), state_hash(phased)) << "tick " << t;
    }
  }
  // the run got somewhere: the robots no longer all show one colour
  EXPECT_GE(std::set<Led>(fused.leds.begin(), fused.leds.end()).size(), 2u);
}

TEST(Determinism, PhysicsRegionsGiveTheSameRunTwice) {
  // robots cross between 2 x 2 Box2D worlds (an open 6 m x 4 m arena) many times
  const Scenario s = with_max_ticks(test::small_arena("[simulation]\nphysics_regions = [2, 2]\n", 12), 3000);
  World end;
  const Metrics a = run(Params{}, s, Mode::kDiffusion, 3, {}, &end);
  const Metrics b = evaluate(Params{}, s, Mode::kDiffusion, 3);
  EXPECT_EQ(a.state_hash, b.state_hash);
  // deployed at x < 0, some end at x > 0: they crossed into the other worlds
  int east = 0;
  for (const Vec2& q : end.positions) east += q.x > 0.0 ? 1 : 0;
  EXPECT_GE(east, 2);
}

}  // namespace
}  // namespace swarmpath::sim
