// SPDX-License-Identifier: MIT
// Determinism as a tested feature (Box2D's habit): a golden state_hash, equal results on
// repeated runs, and equal results when many threads simulate at once.
// Golden values belong to one toolchain: Debian bookworm, g++ 12, libbox2d 2.4.1.
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

}  // namespace
}  // namespace swarmpath::sim
