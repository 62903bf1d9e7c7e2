// SPDX-License-Identifier: MIT
// The range-and-bearing medium by kind (World::rab_by_kind): handing each robot only the kinds of
// message its state reads (rab_interest) must leave every run as it was with every message handed
// to every robot that listens. Whole task-allocation runs, tick by tick, with the switches that add
// readers of the inbox (rest_recruit, recruit_call, refound_starved, founder_seniority) on and off.
#include <cstddef>
#include <string>

#include <gtest/gtest.h>

#include "sim/controllers/ta_protocol.hpp"
#include "sim/hash.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

struct Medium {
  World world;
  MetricsAccumulator metrics;
  std::size_t heard = 0;  // messages handed to robots so far
};

Medium start(const Scenario& s, const Params& p, std::uint64_t seed, bool by_kind) {
  Medium m{make_world(s, p, Mode::kTaskAllocation, seed), {}, 0};
  m.world.rab_by_kind = by_kind;
  m.metrics.begin(m.world.robot_count());
  return m;
}

void tick(const Scenario& s, const Params& p, Medium& m) {
  // the phases of step(), so that the inbox can be counted after sensing
  sense_all(s, p, m.world);
  m.heard += m.world.rab_inbox.size();
  control_all(p, m.world);
  act_all(m.world);
  integrate(s, m.world, m.metrics);
  m.metrics.observe(s, m.world);
}

// Runs both media side by side to `ticks` (or completion) and returns the messages each handed out.
std::pair<std::size_t, std::size_t> expect_same_run(const Scenario& s, const Params& p, std::uint64_t seed,
                                                    std::int64_t ticks, const std::string& what) {
  Medium by_kind = start(s, p, seed, true);
  Medium to_all = start(s, p, seed, false);
  for (std::int64_t t = 0; t < ticks; ++t) {
    tick(s, p, by_kind);
    tick(s, p, to_all);
    const std::uint64_t a = state_hash(by_kind.world);
    const std::uint64_t b = state_hash(to_all.world);
    if (a != b) {
      ADD_FAILURE() << what << ": the runs part at tick " << t << " (0x" << to_hex(a) << " by kind, 0x"
                    << to_hex(b) << " to all)";
      break;
    }
    if (by_kind.metrics.complete() && to_all.metrics.complete()) break;
  }
  return {by_kind.heard, to_all.heard};
}

Scenario paper(int env, int robots) { return with_robots(load_scenario(test::paper_env(env)), robots); }

TEST(RabMedium, ByKindRunsAsEveryMessageToEveryListener) {
  // env4 60 robots seed 1: a chain's end starves, goes home and allocates from the resting robots
  // (refound_starved: T12, then T11's recalls) after tick 5 800
  Params p;
  test::hasty_along_walls(p);  // as measured
  const auto [kind4, all4] = expect_same_run(paper(4, 60), p, 1, 6500, "env4, defaults");
  EXPECT_LT(kind4, all4 / 10) << "the medium by kind should skip most of the crowd's chatter";
  // env1 70 robots seed 3: several founders (founder_seniority's case)
  const Params single = load_params(test::source_path("genomes/paper-single.toml"));
  const auto [kind1, all1] = expect_same_run(paper(1, 70), single, 3, 4000, "env1, paper-single");
  EXPECT_LT(kind1, all1);
}

TEST(RabMedium, ByKindRunsAsToAllWithEachReaderSwitchedOff) {
  Params p = load_params(test::source_path("genomes/paper-single.toml"));
  p.rest_recruit = false;
  expect_same_run(paper(1, 60), p, 2, 3000, "rest_recruit off");
  p = load_params(test::source_path("genomes/paper-single.toml"));
  p.recruit_call = false;
  p.refound_starved = false;
  expect_same_run(paper(1, 60), p, 2, 3000, "recruit_call and refound_starved off");
  p = load_params(test::source_path("genomes/paper-single.toml"));
  p.founder_seniority = false;
  p.single_child = false;
  expect_same_run(paper(1, 70), p, 3, 3000, "founder_seniority and single_child off");
}

// Packet loss (sim/faults.hpp) draws a loss for every message a robot is handed: under it the medium
// hands every message to every listener, so that a run with loss stays the run the fault model defines.
TEST(RabMedium, UnderPacketLossEveryListenerIsHandedEveryMessage) {
  Scenario s = paper(1, 20);
  EXPECT_TRUE(make_world(s, Params{}, Mode::kTaskAllocation, 1).rab_by_kind);
  s.faults.packet_loss = 0.2;
  EXPECT_FALSE(make_world(s, Params{}, Mode::kTaskAllocation, 1).rab_by_kind);
}

TEST(RabMedium, MessageKindsNameTheirReaders) {
  TaMessage request;
  request.type = MsgType::kRequest;
  EXPECT_EQ(message_kinds(request), kKindFounder);
  TaMessage join;
  join.type = MsgType::kJoin;
  join.dest = 4;
  EXPECT_EQ(message_kinds(join), kKindJoin);
  EXPECT_EQ(message_kinds(claim_message(3, 9)), kKindClaim);
  EXPECT_EQ(message_kinds(fetch_message(3, 9)), kKindFetch);
  EXPECT_EQ(message_kinds(alloc_done_message(3, 4)), kKindAllocDone);
  TaMessage recall_ack;
  recall_ack.type = MsgType::kAck;
  recall_ack.flags = kFlagRecall;
  EXPECT_EQ(message_kinds(recall_ack), kKindFounder | kKindRecall);
}

}  // namespace
}  // namespace swarmpath::sim
