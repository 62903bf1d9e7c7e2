// SPDX-License-Identifier: MIT
// The wire form of batches and results (what MPI ranks exchange): every field survives bit for
// bit, a decoded scenario and params set simulate to the same state hash, and truncated or
// corrupt messages are errors, never garbage.
#include "evolve/task_codec.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "evolve_test_support.hpp"
#include "sim/arenas/registry.hpp"
#include "sim/step.hpp"

namespace swarmpath::evolve {
namespace {

template <typename T, typename Write, typename Read>
T round_trip(const T& value, Write write, Read read) {
  ByteWriter w;
  write(w, value);
  const std::vector<char> bytes = w.take();
  ByteReader r(bytes);
  T back = read(r);
  EXPECT_TRUE(r.at_end());
  return back;
}

std::vector<char> scenario_bytes(const sim::Scenario& s) {
  ByteWriter w;
  write_scenario(w, s);
  return w.take();
}

std::vector<char> metrics_bytes(const sim::Metrics& m) {
  ByteWriter w;
  write_metrics(w, m);
  return w.take();
}

// every parameter of the table moved off its default (reals inside their range, flags flipped)
sim::Params unusual_params() {
  sim::Params p;
  for (const sim::ParamInfo& info : sim::param_table()) {
    const double v = sim::get_value(p, info);
    const bool discrete = info.type == sim::ParamType::kBool || info.type == sim::ParamType::kChoice;
    sim::set_value(p, info, discrete ? 1.0 - v : info.lo + 0.3711 * (info.hi - info.lo));
  }
  return p;
}

TEST(TaskCodec, AScenarioWithEveryKindOfObstacleSurvives) {
  sim::Scenario s = sim::load_scenario(testing::source("configs/scenarios/paper/env4.toml"));
  ASSERT_FALSE(s.boxes.empty());
  ASSERT_FALSE(s.cylinders.empty());
  s = sim::with_max_ticks(sim::with_robots(s, 30), 1500);
  s.sim.occlude_by_robots = true;  // off by default: a flag that must travel
  s.sim.physics_regions_x = 2;
  s = sim::with_faults(s, {.fail_fraction = 0.1,
                           .fail_from = 3,
                           .fail_until = 700,
                           .fail_target = sim::FailTarget::kChain,
                           .packet_loss = 0.2,
                           .heading_noise = 1});
  const sim::Scenario back = round_trip(s, write_scenario, read_scenario);
  EXPECT_EQ(scenario_bytes(back), scenario_bytes(s));
  EXPECT_EQ(back.name, s.name);
  EXPECT_EQ(back.file, s.file);
  EXPECT_EQ(back.env_class, s.env_class);
  EXPECT_EQ(back.boxes.size(), s.boxes.size());
  EXPECT_EQ(back.boxes[0].yaw, s.boxes[0].yaw);
  EXPECT_EQ(back.cylinders[0].radius, s.cylinders[0].radius);
  EXPECT_EQ(back.deployment.center, s.deployment.center);
  EXPECT_EQ(back.robots, 30);
  EXPECT_EQ(back.sim.max_ticks, 1500);
  EXPECT_TRUE(back.sim.occlude_by_robots);
  EXPECT_EQ(back.sim.physics_regions_x, 2);
  EXPECT_EQ(back.faults.fail_until, 700);
  EXPECT_EQ(back.faults.fail_target, sim::FailTarget::kChain);
  EXPECT_EQ(back.faults.packet_loss, 0.2);
  // what a remote rank simulates is what this one would
  const sim::Params p;
  EXPECT_EQ(sim::evaluate(p, back, sim::Mode::kTaskAllocation, 5).state_hash,
            sim::evaluate(p, s, sim::Mode::kTaskAllocation, 5).state_hash);
}

TEST(TaskCodec, AGeneratedArenaSurvivesWithItsOrigin) {
  // a generated arena exists in memory only: what a remote rank gets is all it has
  const sim::Scenario s =
      sim::arenas::generate_arena(sim::arenas::default_spec("clutter", "test"), 11).scenario;
  ASSERT_TRUE(s.origin.has_value());
  ASSERT_GT(s.cylinders.size() + s.boxes.size(), 3u);
  const sim::Scenario back = round_trip(s, write_scenario, read_scenario);
  ASSERT_TRUE(back.origin.has_value());
  EXPECT_EQ(back.origin->family, "clutter");
  EXPECT_EQ(back.origin->seed, s.origin->seed);
  EXPECT_EQ(back.origin->version, s.origin->version);
  EXPECT_EQ(back.origin->params, s.origin->params);
  EXPECT_EQ(scenario_bytes(back), scenario_bytes(s));
  const sim::Scenario small = sim::with_max_ticks(sim::with_robots(s, 20), 400);
  EXPECT_EQ(sim::evaluate(sim::Params{}, round_trip(small, write_scenario, read_scenario),
                          sim::Mode::kPathFormation, 3)
                .state_hash,
            sim::evaluate(sim::Params{}, small, sim::Mode::kPathFormation, 3).state_hash);
  EXPECT_FALSE(round_trip(sim::Scenario{}, write_scenario, read_scenario).origin.has_value());
}

TEST(TaskCodec, EveryParameterSurvives) {
  const sim::Params p = unusual_params();
  const sim::Params back = round_trip(p, write_params, read_params);
  for (const sim::ParamInfo& info : sim::param_table()) {
    EXPECT_EQ(sim::get_value(back, info), sim::get_value(p, info)) << info.name;
    EXPECT_NE(sim::get_value(back, info), sim::get_value(sim::Params{}, info))
        << info.name << " kept its default";
  }
}

TEST(TaskCodec, MetricsSurviveBitForBitNaNsAndPathsIncluded) {
  const sim::Scenario s =
      sim::with_max_ticks(sim::load_scenario(testing::source("tests/data/short_chain.toml")), 6000);
  const sim::Metrics done = sim::evaluate(sim::Params{}, s, sim::Mode::kPathFormation, 1);
  ASSERT_TRUE(done.success) << "the test wants a run that forms its path";
  ASSERT_FALSE(done.final_path.points.empty());
  const sim::Metrics back = round_trip(done, write_metrics, read_metrics);
  EXPECT_EQ(metrics_bytes(back), metrics_bytes(done));
  EXPECT_EQ(back.state_hash, done.state_hash);
  EXPECT_EQ(back.path_length_tu, done.path_length_tu);
  EXPECT_EQ(back.final_path.robots, done.final_path.robots);
  EXPECT_EQ(back.final_path.points, done.final_path.points);
  EXPECT_EQ(back.chain.subgoals_laid, done.chain.subgoals_laid);
  sim::Metrics faulty = done;  // the fault counts travel too
  faulty.failures = 3;
  faulty.chain_failures = 2;
  const sim::Metrics fback = round_trip(faulty, write_metrics, read_metrics);
  EXPECT_EQ(fback.failures, 3);
  EXPECT_EQ(fback.chain_failures, 2);

  // a run that never formed its path: NaN lengths stay NaN, -1 ticks stay -1
  const sim::Metrics failed =
      sim::evaluate(sim::Params{}, sim::with_max_ticks(s, 50), sim::Mode::kTaskAllocation, 1);
  ASSERT_FALSE(failed.success);
  const sim::Metrics fb = round_trip(failed, write_metrics, read_metrics);
  EXPECT_TRUE(std::isnan(fb.path_length_tu));
  EXPECT_TRUE(std::isnan(fb.resource_reduction_pct) == std::isnan(failed.resource_reduction_pct));
  EXPECT_EQ(fb.ticks_to_form, -1);
  EXPECT_EQ(metrics_bytes(fb), metrics_bytes(failed));
}

TEST(TaskCodec, ABatchSurvivesWithItsTasks) {
  SimBatch b;
  const auto s = std::make_shared<const sim::Scenario>(
      sim::load_scenario(testing::source("tests/data/short_chain.toml")));
  b.add_scenario(s);
  b.add_params(sim::Params{});
  b.add_params(unusual_params());
  b.tasks = {{1, 0, sim::Mode::kTaskAllocation, 0xfedcba9876543210ULL}, {0, 0, sim::Mode::kPathFormation, 7}};
  ByteWriter w;
  write_batch(w, b);
  const std::vector<char> bytes = w.take();
  ByteReader r(bytes);
  const SimBatch back = read_batch(r);
  ASSERT_EQ(back.tasks.size(), 2u);
  EXPECT_EQ(back.tasks[0].params, 1u);
  EXPECT_EQ(back.tasks[0].mode, sim::Mode::kTaskAllocation);
  EXPECT_EQ(back.tasks[0].seed, 0xfedcba9876543210ULL);
  EXPECT_EQ(back.tasks[1].seed, 7u);
  ASSERT_EQ(back.params.size(), 2u);
  EXPECT_EQ(back.params[1].v_max, b.params[1].v_max);
  ASSERT_EQ(back.scenarios.size(), 1u);
  EXPECT_EQ(scenario_bytes(*back.scenarios[0]), scenario_bytes(*s));
}

TEST(TaskCodec, TruncatedOrCorruptMessagesAreErrors) {
  SimBatch b;
  b.add_scenario(std::make_shared<const sim::Scenario>(
      sim::load_scenario(testing::source("tests/data/short_chain.toml"))));
  b.add_params(sim::Params{});
  b.tasks = {{0, 0, sim::Mode::kPathFormation, 1}};
  ByteWriter w;
  write_batch(w, b);
  std::vector<char> bytes = w.take();
  for (const std::size_t cut : {std::size_t{0}, std::size_t{5}, bytes.size() / 2, bytes.size() - 1}) {
    ByteReader r(std::span<const char>(bytes.data(), cut));
    EXPECT_THROW(read_batch(r), std::runtime_error) << "cut at " << cut;
  }
  // the last task names params set 0 in its last 8 + 1 + 4 + 4 bytes: make it name set 9
  bytes[bytes.size() - 17] = 9;
  ByteReader r(bytes);
  try {
    read_batch(r);
    ADD_FAILURE() << "a task naming a missing params set was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing params set"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace swarmpath::evolve
