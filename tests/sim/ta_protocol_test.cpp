// SPDX-License-Identifier: MIT
// The task-allocation protocol in isolation (paper, "Local Communication Protocol"; SPEC §2.6):
// one founder and k decision makers over a scripted medium that delivers one tick later, and
// may lose or delay messages; the framing; and Eq. (1)-(3).
#include "sim/controllers/ta_protocol.hpp"

#include <map>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace swarmpath::sim {
namespace {

TEST(TaFraming, EveryFieldOfAFounderMessageSurvivesTheTenBytes) {
  TaMessage m;
  m.id = 17;
  m.flags = kFlagAllocDone | kFlagGoal | kFlagRecall;
  m.type = MsgType::kAck;
  m.dest = 99;
  m.remaining = 253;
  m.t_founder_ds = 0xbeef;
  m.goal_x_cm = -1350;  // R: the goal sighting relative to the nest, signed cm
  m.goal_y_cm = 275;
  const RabPayload p = encode(m);
  EXPECT_EQ(p.size(), 10u);  // SPEC §2.6: 10 bytes
  EXPECT_EQ(p[0], 17);       // SPEC: byte 0 the sender's id
  EXPECT_EQ(p[4], 3);        // byte 4 the message type
  EXPECT_EQ(p[5], 99);       // byte 5 the destination
  EXPECT_EQ(p[6], 253);      // byte 6 remaining (R: one byte)
  EXPECT_EQ(p[8], 0xbe);     // bytes 8-9 t_founder/10
  EXPECT_EQ(p[9], 0xef);
  const TaMessage back = decode(p);
  EXPECT_EQ(back.id, 17);
  EXPECT_EQ(back.state, kFounderState);  // a founder message's state is GOAL_FOUNDER
  EXPECT_EQ(back.parent, kBroadcastId);
  EXPECT_EQ(back.flags, kFlagAllocDone | kFlagGoal | kFlagRecall);
  EXPECT_EQ(back.type, MsgType::kAck);
  EXPECT_EQ(back.dest, 99);
  EXPECT_EQ(back.remaining, 253);
  EXPECT_EQ(back.t_founder_ds, 0xbeef);
  EXPECT_TRUE(back.has_goal());
  EXPECT_EQ(back.goal_x_cm, -1350);  // within +-20.47 m: to the centimetre
  EXPECT_EQ(back.goal_y_cm, 275);
}

TEST(TaFraming, AClaimKeepsItsStateAndParentBytes) {
  TaMessage m = claim_message(40, 12);
  m.flags = kFlagNeed | kFlagGoal;  // no room for a goal outside a founder message
  const RabPayload p = encode(m);
  EXPECT_EQ(p[1], kClaimState);  // SPEC: byte 1 state, byte 2 parent
  EXPECT_EQ(p[2], 12);
  const TaMessage back = decode(p);
  EXPECT_EQ(back.state, kClaimState);
  EXPECT_EQ(back.parent, 12);
  EXPECT_EQ(back.flags, kFlagNeed);
  EXPECT_FALSE(back.has_goal());
  EXPECT_EQ(claimed_emitter(back), 12);
}

// the goal's x and y as they come back from a founder's REQUEST
std::pair<int, int> goal_round_trip(int x_cm, int y_cm) {
  TaMessage m;
  m.type = MsgType::kRequest;
  m.flags = kFlagGoal;
  m.goal_x_cm = x_cm;
  m.goal_y_cm = y_cm;
  const TaMessage back = decode(encode(m));
  EXPECT_TRUE(back.has_goal());
  return {back.goal_x_cm, back.goal_y_cm};
}

TEST(TaFraming, TheGoalTravelsToTheCentimetreWithinTwentyMetresAndCoarserBeyond) {
  using P = std::pair<int, int>;
  EXPECT_EQ(goal_round_trip(1594, 0), P(1594, 0));          // the paper's farthest goal (env6, 15.94 m)
  EXPECT_EQ(goal_round_trip(2047, -2047), P(2047, -2047));  // the 1 cm unit's edge
  EXPECT_EQ(goal_round_trip(-2048, 3), P(-2050, 0));        // one step beyond: 10 cm, rounded
  EXPECT_EQ(goal_round_trip(-15949, 20467), P(-15950, 20470));
  EXPECT_EQ(goal_round_trip(150049, -199951), P(150000, -200000));  // 1 m: any arena (kMaxArenaSide)
  EXPECT_EQ(goal_round_trip(1000000000, -5), P(204700, 0));         // beyond +-2 047 m: clamped
}

TEST(TaFraming, AnUnknownTypeDecodesAsNone) {
  RabPayload p{};
  p[4] = 9;
  EXPECT_EQ(decode(p).type, MsgType::kNone);
}

// lead_way [R]: a corner of the founder's way is a message of its own type that no reader of the
// protocol takes for a claim, a fetch, a founder's message or ALLOC_DONE.
TEST(TaFraming, AWayCornerTravelsToTheCentimetreAndIsNoOtherMessage) {
  for (const WayCorner c : {WayCorner{0, 15, -1794.0, 32.0}, WayCorner{14, 15, 32767.0, -32767.0},
                            WayCorner{3, 16, 3.0, 1.0}}) {  // state byte 0, parent byte 3: no claim
    const RabPayload p = way_message(42, c);
    const TaMessage m = decode(p);
    EXPECT_EQ(m.id, 42);
    EXPECT_EQ(m.type, MsgType::kWay);
    EXPECT_EQ(message_kinds(m), kKindWay);
    EXPECT_EQ(claimed_emitter(m), kNobody);
    EXPECT_EQ(fetch_for(m), kNobody);
    const WayCorner back = way_corner(p);
    EXPECT_EQ(back.index, c.index);
    EXPECT_EQ(back.count, c.count);
    EXPECT_EQ(back.x_cm, c.x_cm);
    EXPECT_EQ(back.y_cm, c.y_cm);
  }
  // beyond 327 m of the nest the corner travels in a coarser unit, never clamped: 400 m, and the far
  // corner of the largest arena (kMaxArenaSide, 2 km a side: 2.8 km from the nest), to the decimetre
  const WayCorner far = way_corner(way_message(1, {0, 1, 40000.0, -40003.0}));
  EXPECT_EQ(far.x_cm, 40000.0);
  EXPECT_EQ(far.y_cm, -40000.0);
  EXPECT_EQ(claimed_emitter(decode(way_message(1, {0, 1, 40000.0, -40003.0}))), kNobody);
  EXPECT_EQ(decode(way_message(1, {0, 1, 40000.0, -40003.0})).flags, 0);
  const WayCorner farthest = way_corner(way_message(1, {0, 1, -282842.7, 199999.6}));
  EXPECT_NEAR(farthest.x_cm, -282842.7, 50.0);
  EXPECT_NEAR(farthest.y_cm, 199999.6, 50.0);
  EXPECT_EQ(message_kinds(decode(encode(TaMessage{}))) & kKindWay, 0U);  // nor is any other
}

TEST(TaEquations, WorkedExampleOfSpec27) {
  // t = 150 s, s = 10 cm/s -> l = 1500 cm -> n0 = 15 -> delta_open 5 -> n = 20 (RR 80 % of 100)
  EXPECT_EQ(robots_needed(150.0, 10.0, 100.0, 5.0, 2, 100), 20);
  EXPECT_EQ(robots_needed(150.0, 10.0, 100.0, 15.0, 2, 100), 30);  // delta_obstacle
  EXPECT_EQ(robots_needed(151.0, 10.0, 100.0, 5.0, 2, 100), 21);   // ceil
  EXPECT_EQ(robots_needed(150.0, 10.0, 100.0, 5.0, 2, 12), 12);    // clamped to N
  EXPECT_EQ(robots_needed(0.0, 10.0, 100.0, 0.0, 2, 100), 2);      // clamped to n_min
}

// ---- a scripted medium ----

struct Sent {
  std::int64_t deliver_at;
  int sender;
  RabPayload data;
};

// One founder (id 0) and k decision makers (ids 1..k, robot i at 10 i cm from the founder).
// `lose(tick, sender, receiver)` drops a message; `delay(tick, sender)` adds ticks to its latency.
struct Exchange {
  int k = 0;
  int need = 0;        // robots the founder asks for
  bool resend = true;  // resend_lost_ack
  std::function<bool(std::int64_t, int, int)> lose = [](std::int64_t, int, int) { return false; };
  std::function<int(std::int64_t, int)> delay = [](std::int64_t, int) { return 0; };

  FounderProtocol founder;
  std::map<int, DmDecision> decided;  // decision maker -> go / rest
  std::vector<int> went;              // in the order they left

  void run(int done_for, std::int64_t max_ticks = 2000) {
    founder = start_founder(need);
    std::vector<Sent> air;
    for (std::int64_t t = 0; t < max_ticks; ++t) {
      // what each robot hears this tick
      std::vector<std::vector<RabMessage>> inbox(static_cast<std::size_t>(k + 1));
      for (const Sent& s : air) {
        if (s.deliver_at != t) continue;
        for (int r = 0; r <= k; ++r) {
          if (r == s.sender || lose(t, s.sender, r)) continue;
          RabMessage m;
          m.sender = s.sender;
          m.data = s.data;
          m.range_cm = 10.0 * std::abs(r - s.sender);
          inbox[static_cast<std::size_t>(r)].push_back(m);
        }
      }
      std::erase_if(air, [t](const Sent& s) { return s.deliver_at <= t; });
      // the founder, then every decision maker still at the nest
      const TaMessage f = founder_tick(founder, 0, 150, inbox[0], resend);
      air.push_back({t + 1 + delay(t, 0), 0, encode(f)});
      for (int i = 1; i <= k; ++i) {
        if (decided.count(i) != 0) continue;
        const DmTick d =
            decision_maker_tick(static_cast<std::uint8_t>(i), inbox[static_cast<std::size_t>(i)]);
        if (d.decision != DmDecision::kWait) {
          decided[i] = d.decision;
          if (d.decision == DmDecision::kGo) went.push_back(i);
          continue;
        }
        if (d.send.type == MsgType::kJoin) air.push_back({t + 1 + delay(t, i), i, encode(d.send)});
      }
      if (founder.finished(done_for) && static_cast<int>(decided.size()) == k) return;
    }
  }

  std::set<int> acked_ids() const {
    std::set<int> ids;
    for (int i = 0; i < 256; ++i) {
      if (founder.is_acked(static_cast<std::uint8_t>(i))) ids.insert(i);
    }
    return ids;
  }
};

TEST(TaProtocol, ExactlyTheNeededRobotsGetAcksAndTheRestRest) {
  Exchange x;
  x.k = 12;
  x.need = 5;
  x.run(/*done_for=*/5);
  EXPECT_EQ(x.founder.acks, 5);
  EXPECT_EQ(x.founder.remaining, 0);
  ASSERT_EQ(x.went.size(), 5u);
  // one ACK per tick, each to the nearest JOIN: robots 1..5, in that order
  EXPECT_EQ(x.went, (std::vector<int>{1, 2, 3, 4, 5}));
  EXPECT_EQ(x.acked_ids(), (std::set<int>{1, 2, 3, 4, 5}));
  for (int i = 6; i <= 12; ++i) EXPECT_EQ(x.decided[i], DmDecision::kRest) << "robot " << i;
}

TEST(TaProtocol, FewerDecisionMakersThanNeededAllGo) {
  Exchange x;
  x.k = 3;
  x.need = 10;
  x.run(5, 300);
  EXPECT_EQ(x.went.size(), 3u);
  EXPECT_EQ(x.founder.acks, 3);
  EXPECT_EQ(x.founder.remaining, 7);  // still asking: nobody else is there to answer
}

TEST(TaProtocol, LostAcksAreRepeatedWithoutCountingARobotTwice) {
  Exchange x;
  x.k = 10;
  x.need = 4;
  // the founder's first three ACKs to robot 1, and every ACK to robot 2 sent before tick 20, are lost
  int lost_to_1 = 0;
  x.lose = [&](std::int64_t t, int sender, int receiver) {
    if (sender != 0) return false;
    if (receiver == 1 && lost_to_1 < 3) return ++lost_to_1, true;
    return receiver == 2 && t < 20;
  };
  x.run(5);
  EXPECT_EQ(x.founder.acks, 4);
  EXPECT_EQ(x.acked_ids().size(), 4u);  // four distinct robots
  const std::set<int> went(x.went.begin(), x.went.end());
  EXPECT_EQ(went.size(), x.went.size());  // nobody went twice
  EXPECT_EQ(went, x.acked_ids());         // the robots that went are the robots counted
}

// resend_lost_ack off: a robot whose ACK was lost JOINs again and is ignored; it is counted, never leaves
TEST(TaProtocol, WithoutTheResendARobotWhoseAckWasLostIsCountedButStays) {
  Exchange x;
  x.k = 10;
  x.need = 4;
  x.resend = false;
  // REQUEST at tick 0, JOINs at 1, the first ACK (to robot 1, the nearest) at 2, delivered at 3: lost
  x.lose = [](std::int64_t t, int sender, int receiver) { return sender == 0 && receiver == 1 && t == 3; };
  x.run(5);
  EXPECT_EQ(x.founder.acks, 4);
  EXPECT_TRUE(x.acked_ids().contains(1));
  EXPECT_EQ(x.went.size(), 3u);  // robot 1 was counted but rested
  EXPECT_EQ(x.decided[1], DmDecision::kRest);
}

TEST(TaProtocol, LostAndLateJoinsDoNotAllocateTwice) {
  Exchange x;
  x.k = 15;
  x.need = 6;
  // every third JOIN is lost, every other one arrives 1-3 ticks late
  x.lose = [](std::int64_t t, int sender, int receiver) {
    return sender != 0 && receiver == 0 && (t + sender) % 3 == 0;
  };
  x.delay = [](std::int64_t t, int sender) { return sender != 0 && (t + sender) % 2 == 0 ? 1 + (t % 3) : 0; };
  x.run(5);
  EXPECT_EQ(x.founder.acks, 6);
  EXPECT_EQ(x.acked_ids().size(), 6u);
  const std::set<int> went(x.went.begin(), x.went.end());
  EXPECT_EQ(went.size(), x.went.size());
  EXPECT_TRUE(std::includes(x.acked_ids().begin(), x.acked_ids().end(), went.begin(), went.end()));
  EXPECT_LE(x.went.size(), 6u);
  int rested = 0;
  for (const auto& [id, d] : x.decided) rested += d == DmDecision::kRest ? 1 : 0;
  EXPECT_EQ(rested + static_cast<int>(x.went.size()), 15);  // everyone decided
}

TEST(TaProtocol, DuplicateFoundersDeferToTheSmallerId) {
  TaMessage req;
  req.type = MsgType::kRequest;
  std::vector<RabMessage> inbox(2);
  req.id = 9;
  inbox[0].data = encode(req);
  req.id = 4;
  inbox[1].data = encode(req);
  EXPECT_EQ(senior_founder_heard({false, 7}, inbox), 4);
  EXPECT_EQ(senior_founder_heard({false, 3}, inbox), kBroadcastId);  // 3 is the smallest: it stays founder
  // a decision maker hearing both joins the smaller one
  const DmTick d = decision_maker_tick(20, inbox);
  EXPECT_EQ(d.send.type, MsgType::kJoin);
  EXPECT_EQ(d.send.dest, 4);
}

// founder_seniority [R]: a founder that has ACKed robots keeps its allocation; a late founder with a
// smaller id defers to it instead of starting a second one (env1, 70 robots, seed 3: 70 allocated
// by four founders without it)
TEST(TaProtocol, AFounderThatHasAllocatedOutranksASmallerIdWithSeniority) {
  FounderProtocol senior = start_founder(5);
  std::vector<RabMessage> joins(1);
  TaMessage join;
  join.id = 30;
  join.type = MsgType::kJoin;
  join.dest = 9;
  joins[0].data = encode(join);
  const TaMessage ack = founder_tick(senior, 9, 100, joins);  // founder 9 ACKs robot 30
  ASSERT_EQ(ack.type, MsgType::kAck);
  EXPECT_TRUE(ack.allocating());
  TaMessage late;  // founder 4 arrives and requests
  late.id = 4;
  late.type = MsgType::kRequest;
  std::vector<RabMessage> inbox(2);
  inbox[0].data = encode(ack);
  inbox[1].data = encode(late);
  // with seniority: 4 (no ACK yet) defers to 9, 9 does not defer to 4, decision makers join 9
  EXPECT_EQ(senior_founder_heard({false, 4}, inbox, true), 9);
  EXPECT_EQ(senior_founder_heard({true, 9}, inbox, true), kBroadcastId);
  EXPECT_EQ(decision_maker_tick(20, inbox, true).send.dest, 9);
  // without it the smaller id wins, whatever it has allocated (SPEC T8)
  EXPECT_EQ(senior_founder_heard({false, 4}, inbox, false), kBroadcastId);
  EXPECT_EQ(senior_founder_heard({true, 9}, inbox, false), 4);
  EXPECT_EQ(decision_maker_tick(20, inbox, false).send.dest, 4);
}

TEST(TaProtocol, AnAckedDecisionMakerLearnsWhereTheGoalWasSeen) {  // R: share_goal
  TaMessage ack;
  ack.id = 3;
  ack.type = MsgType::kAck;
  ack.dest = 12;
  ack.t_founder_ds = 100;
  std::vector<RabMessage> inbox(1);
  inbox[0].data = encode(ack);
  EXPECT_FALSE(decision_maker_tick(12, inbox).ack.has_goal());  // a founder that does not share it
  ack.flags = kFlagGoal;
  ack.goal_x_cm = 1300;
  ack.goal_y_cm = -40;
  inbox[0].data = encode(ack);
  const DmTick d = decision_maker_tick(12, inbox);
  EXPECT_EQ(d.decision, DmDecision::kGo);
  EXPECT_TRUE(d.ack.has_goal());
  EXPECT_EQ(d.ack.goal_x_cm, 1300);
  EXPECT_EQ(d.ack.goal_y_cm, -40);
  EXPECT_FALSE(decision_maker_tick(13, inbox).ack.has_goal());  // addressed to another robot
}

TEST(TaProtocol, AllocDoneFlagSendsADecisionMakerToRest) {
  TaMessage resting;
  resting.id = 30;
  resting.flags = kFlagAllocDone;  // a resting robot's beacon (SPEC T6)
  std::vector<RabMessage> inbox(1);
  inbox[0].data = encode(resting);
  EXPECT_EQ(decision_maker_tick(5, inbox).decision, DmDecision::kRest);
}

TEST(TaProtocol, AClaimNamesTheGoalOrTheSubgoal) {  // R: single_child
  EXPECT_EQ(claimed_emitter(decode(encode(claim_message(5, 17)))), 17);
  EXPECT_EQ(claimed_emitter(decode(encode(claim_message(5, kGoalEmitter)))), kGoalEmitter);
  EXPECT_EQ(claimed_emitter(decode(encode(claim_message(5, 0)))), 0);
  // the protocol's own messages claim nothing
  TaMessage req;
  req.id = 4;
  req.type = MsgType::kRequest;
  req.parent = 17;
  EXPECT_EQ(claimed_emitter(decode(encode(req))), kNobody);
  TaMessage resting;
  resting.id = 4;
  resting.state = 4;
  resting.flags = kFlagAllocDone;
  EXPECT_EQ(claimed_emitter(decode(encode(resting))), kNobody);
}

}  // namespace
}  // namespace swarmpath::sim
