// SPDX-License-Identifier: MIT
// Batches of simulations: the thread pool returns each task's Metrics in task order at any thread
// count, hands out the longest expected tasks first, stores scenarios once and names a failed task.
#include "evolve/batch.hpp"

#include <memory>
#include <stdexcept>

#include <gtest/gtest.h>

#include "evolve_test_support.hpp"
#include "sim/step.hpp"

namespace swarmpath::evolve {
namespace {

std::shared_ptr<const sim::Scenario> short_chain(int robots, std::int64_t ticks) {
  const sim::Scenario s = sim::load_scenario(testing::source("tests/data/short_chain.toml"));
  return std::make_shared<const sim::Scenario>(sim::with_max_ticks(sim::with_robots(s, robots), ticks));
}

// two scenarios x two params sets x two seeds, both modes
SimBatch small_batch() {
  SimBatch b;
  const std::uint32_t s8 = b.add_scenario(short_chain(8, 400));
  const std::uint32_t s12 = b.add_scenario(short_chain(12, 300));
  sim::Params fast;
  fast.v_max = 30;
  const std::uint32_t p0 = b.add_params(sim::Params{});
  const std::uint32_t p1 = b.add_params(fast);
  for (const std::uint32_t p : {p0, p1}) {
    for (const std::uint32_t s : {s8, s12}) {
      for (const std::uint64_t seed : {3u, 4u}) {
        b.tasks.push_back({p, s, seed == 3 ? sim::Mode::kPathFormation : sim::Mode::kTaskAllocation, seed});
      }
    }
  }
  return b;
}

TEST(Batch, ThreadPoolGivesEachTasksMetricsInTaskOrderAtAnyThreadCount) {
  const SimBatch b = small_batch();
  for (const int threads : {1, 3}) {
    ThreadPool pool(threads);
    std::size_t last_done = 0;
    const std::vector<sim::Metrics> m = pool.run(b, [&](std::size_t done, std::size_t total) {
      EXPECT_EQ(total, b.tasks.size());
      last_done = done;
    });
    ASSERT_EQ(m.size(), b.tasks.size());
    EXPECT_EQ(last_done, b.tasks.size());
    for (std::size_t k = 0; k < b.tasks.size(); ++k) {
      const SimTask& t = b.tasks[k];
      const sim::Metrics want = sim::evaluate(b.params[t.params], *b.scenarios[t.scenario], t.mode, t.seed);
      EXPECT_EQ(m[k].state_hash, want.state_hash) << "task " << k << ", " << threads << " threads";
      EXPECT_EQ(m[k].ticks, want.ticks) << "task " << k;
      EXPECT_EQ(m[k].robots, b.scenarios[t.scenario]->robots) << "task " << k;
    }
    EXPECT_NE(pool.summary().find(std::to_string(b.tasks.size()) + " simulations"), std::string::npos)
        << pool.summary();
  }
}

TEST(Batch, TheSameScenarioIsStoredOnce) {
  SimBatch b;
  const auto s = short_chain(8, 100);
  EXPECT_EQ(b.add_scenario(s), 0u);
  EXPECT_EQ(b.add_scenario(short_chain(8, 100)), 1u);  // equal, but another object
  EXPECT_EQ(b.add_scenario(s), 0u);
  EXPECT_EQ(b.scenarios.size(), 2u);
}

TEST(Batch, LongestExpectedTasksAreHandedOutFirst) {
  SimBatch b;
  const std::uint32_t small = b.add_scenario(short_chain(8, 1000));   // 8 000 robot-ticks
  const std::uint32_t large = b.add_scenario(short_chain(20, 1000));  // 20 000
  const std::uint32_t longer = b.add_scenario(short_chain(8, 5000));  // 40 000
  b.add_params(sim::Params{});
  b.tasks = {{0, small, sim::Mode::kPathFormation, 1},
             {0, large, sim::Mode::kPathFormation, 1},
             {0, small, sim::Mode::kTaskAllocation, 1},
             {0, longer, sim::Mode::kPathFormation, 1},
             {0, small, sim::Mode::kPathFormation, 2}};
  // 40 000 (3), 20 000 (1), then TA's 8 000 x 1.25 (2), then the two 8 000 in task order
  EXPECT_EQ(handout_order(b), (std::vector<std::uint32_t>{3, 1, 2, 0, 4}));
  EXPECT_GT(expected_cost(*b.scenarios[small], sim::Mode::kTaskAllocation),
            expected_cost(*b.scenarios[small], sim::Mode::kPathFormation));
}

TEST(Batch, AFailedTaskIsNamedOnceTheBatchIsOver) {
  const SimBatch b = small_batch();
  std::vector<std::string> errors(b.tasks.size());
  EXPECT_NO_THROW(throw_first_error(b, errors));
  errors[6] = "second";
  errors[5] = "first";
  try {
    throw_first_error(b, errors);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    // task 5: params 1, scenario short_chain at 8 robots, task allocation, seed 4
    EXPECT_EQ(std::string(e.what()), "evaluation failed (short_chain, 8 robots, ta, seed 4): first");
  }
}

}  // namespace
}  // namespace swarmpath::evolve
