// SPDX-License-Identifier: MIT
// chain_repair [R] (docs/faults.md, rows #18-#20): a chain robot whose neighbour's link light has
// been gone for T_repair ticks mends the chain: it re-links over the gap to the robot its parent's
// light named, or leaves the chain; a robot whose child is gone becomes the chain's tip again. And
// in a small arena, a chain that loses a member forms its path with the rule and not without it.
#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/controllers/path_formation.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

constexpr Vec2 kNest{-5.0, 0.0};
constexpr int kMe = 3;
constexpr int kParent = 7;
constexpr int kHeir = 5;  // whom the parent's light names: the parent's own parent
constexpr int kChild = 12;

Params repairing() {
  Params p;
  p.chain_repair = true;
  return p;
}

// one camera blob in the robot's frame (the robot at the origin facing +x)
Blob blob(Led c, int emitter, double bearing_deg, double distance_cm, int tag) {
  return {c, emitter, unit(deg2rad(bearing_deg)), distance_cm, tag};
}

Percept percept(std::int64_t tick, const std::vector<Blob>& blobs) {
  Percept in;
  in.tick = tick;
  in.id = kMe;
  in.pose = {{0.0, 0.0}, 1.0, 0.0};
  in.blobs = blobs;
  return in;
}

Tracked tracked(int id, Vec2 at, Led c) {
  Tracked t;
  t.id = id;
  t.last_seen = at;
  t.visible = true;
  t.color = c;
  return t;
}

RobotMemory chain_robot(PfState s) {
  RobotMemory mem = init_memory(Mode::kPathFormation, kMe, {{0.0, 0.0}, 1.0, 0.0}, kNest, Params{}, 1);
  mem.pf.state = s;
  mem.pf.parent = tracked(kParent, {0.7, 0.0}, Led::kRed);
  if (s != PfState::kSubgoal) mem.pf.child = tracked(kChild, {-0.7, 0.0}, Led::kBlue);
  return mem;
}

// runs `ticks` control steps: first one with the parent (RED, naming kHeir) and the child in view,
// then `after` each tick; returns the memory
RobotMemory run(PfState s, const std::vector<Blob>& after, int ticks, const Params& p) {
  RobotMemory mem = chain_robot(s);
  const Led child_led = s == PfState::kSubgoal ? Led::kRed : Led::kBlue;
  (void)path_formation_step(
      percept(100, {blob(Led::kRed, kParent, 0, 70, kHeir), blob(child_led, kChild, 180, 70, kMe)}), p, mem);
  for (int t = 1; t <= ticks; ++t) (void)path_formation_step(percept(100 + t, after), p, mem);
  return mem;
}

const Blob kChildInView = blob(Led::kRed, kChild, 180, 70, kMe);
const Blob kHeirInView = blob(Led::kRed, kHeir, 10, 95, 2);

TEST(ChainRepair, AParentGoneDarkIsReplacedByTheRobotItsLightNamed) {
  const Params p = repairing();
  const int t = static_cast<int>(p.t_repair);
  // the parent fails: its light goes dark; the robot it named stands in view beyond it
  const RobotMemory early = run(PfState::kSubgoal, {kChildInView, kHeirInView}, t - 1, p);
  EXPECT_EQ(early.pf.state, PfState::kSubgoal);
  EXPECT_EQ(early.pf.parent.id, kParent);  // not yet: T_repair ticks first
  const RobotMemory relinked = run(PfState::kSubgoal, {kChildInView, kHeirInView}, t, p);
  EXPECT_EQ(relinked.pf.state, PfState::kSubgoal);
  EXPECT_EQ(relinked.pf.parent.id, kHeir);
  EXPECT_EQ(relinked.pf.last_row, pf_row_number("#18a"));
  // a sub-nest re-links the same way (and keeps waiting for its new parent)
  const RobotMemory sub_nest =
      run(PfState::kSubNest, {blob(Led::kBlue, kChild, 180, 70, kMe), kHeirInView}, t, p);
  EXPECT_EQ(sub_nest.pf.state, PfState::kSubNest);
  EXPECT_EQ(sub_nest.pf.parent.id, kHeir);
  // off: the robot waits for its dark parent for ever
  Params off = p;
  off.chain_repair = false;
  const RobotMemory waits = run(PfState::kSubgoal, {kChildInView, kHeirInView}, 5 * t, off);
  EXPECT_EQ(waits.pf.state, PfState::kSubgoal);
  EXPECT_EQ(waits.pf.parent.id, kParent);
}

TEST(ChainRepair, WithNoHeirInViewTheOrphanLeavesAndItsChildFollows) {
  const Params p = repairing();
  const int t = static_cast<int>(p.t_repair);
  const RobotMemory left = run(PfState::kSubgoal, {kChildInView}, t, p);
  EXPECT_EQ(left.pf.state, PfState::kReturnToNest);
  EXPECT_EQ(left.pf.last_row, pf_row_number("#19a"));
  EXPECT_FALSE(left.pf.parent.valid());
  // its child sees the parent in view but GRAY (going home): no link light, gone in turn
  const RobotMemory child =
      run(PfState::kSubgoal, {kChildInView, blob(Led::kGray50, kParent, 0, 70, kNobody)}, t, p);
  EXPECT_EQ(child.pf.state, PfState::kReturnToNest);
  // a parent that only blinks out of view for less than T_repair keeps its place
  RobotMemory mem = chain_robot(PfState::kSubgoal);
  const Blob parent = blob(Led::kRed, kParent, 0, 70, kHeir);
  for (int k = 0; k < 4 * t; ++k) {
    const bool seen = k % (t / 2) == 0;
    (void)path_formation_step(percept(100 + k, seen ? std::vector<Blob>{parent} : std::vector<Blob>{}), p,
                              mem);
  }
  EXPECT_EQ(mem.pf.state, PfState::kSubgoal);
  EXPECT_EQ(mem.pf.parent.id, kParent);
}

TEST(ChainRepair, ARobotWhoseChildIsGoneIsTheChainsTipAgain) {
  const Params p = repairing();
  const int t = static_cast<int>(p.t_repair);
  const Blob parent_done = blob(Led::kBrown, kParent, 0, 70, kHeir);
  // a sub-nest (its parent waiting too) and a robot whose path is done: the child fails (dark)
  for (const PfState s : {PfState::kSubNest, PfState::kPathDone}) {
    const Blob parent = s == PfState::kSubNest ? blob(Led::kBlue, kParent, 0, 70, kHeir) : parent_done;
    const RobotMemory tip = run(s, {parent}, t, p);
    EXPECT_EQ(tip.pf.state, PfState::kSubgoal) << to_string(s);
    EXPECT_FALSE(tip.pf.child.valid());
    EXPECT_EQ(tip.pf.parent.id, kParent);  // still linked goalward
  }
  // a child still in the chain (BLUE, then PURPLE in optimisation 2) is no gap
  const RobotMemory kept =
      run(PfState::kPathDone, {parent_done, blob(Led::kPurple, kChild, 180, 70, kMe)}, 3 * t, p);
  EXPECT_EQ(kept.pf.state, PfState::kPathDone);
}

// short_chain (20 robots, nest and goal 3.6 m apart), path formation: two robots holding chain links
// fail between ticks 200 and 600. Without the rule seeds 4 and 11 form no path in 8 000 ticks;
// with it each does (of seeds 1-12: 8 of 12 without, 10 of 12 with)
TEST(ChainRepair, ABrokenChainInASmallArenaFormsItsPathOnlyWithTheRule) {
  const Scenario s = with_faults(
      with_max_ticks(load_scenario(test::source_path("tests/data/short_chain.toml")), 8000),
      {.fail_fraction = 0.1, .fail_from = 200, .fail_until = 600, .fail_target = FailTarget::kChain});
  // robots that lose their target turn RECOVERY (form_retries = 0): with retries, those that went
  // home also come back to a broken chain's end, and seed 8 forms its path without the rule
  Params spec_lost;
  spec_lost.form_retries = 0;
  spec_lost.chain_repair = false;
  spec_lost.resume_search = false;           // as measured: every trip explores from the nest
  test::pf_links_by_trail_slack(spec_lost);  // as measured
  Params repairing_spec_lost = repairing();
  repairing_spec_lost.form_retries = 0;
  repairing_spec_lost.resume_search = false;
  test::pf_links_by_trail_slack(repairing_spec_lost);
  for (const std::uint64_t seed : {4, 11}) {
    const Metrics off = evaluate(spec_lost, s, Mode::kPathFormation, seed);
    const Metrics on = evaluate(repairing_spec_lost, s, Mode::kPathFormation, seed);
    EXPECT_EQ(off.chain_failures, 2) << seed;
    EXPECT_EQ(on.chain_failures, 2) << seed;
    EXPECT_FALSE(off.success) << seed;
    EXPECT_TRUE(on.success) << seed;
  }
}

}  // namespace
}  // namespace swarmpath::sim
