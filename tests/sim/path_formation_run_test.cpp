// SPDX-License-Identifier: MIT
// Path formation in motion: an aligning robot moves onto the line between its references, a
// short chain forms and both optimisation passes complete, and a golden hash of a whole run.
// Golden values belong to one toolchain: Debian bookworm, g++ 12, libbox2d 2.4.1.
#include <cmath>

#include <gtest/gtest.h>

#include "sim/astar.hpp"
#include "sim/controllers/alignment.hpp"
#include "sim/hash.hpp"
#include "sim/path_metrics.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

Scenario short_chain() { return load_scenario(test::source_path("tests/data/short_chain.toml")); }

Pose at(double x, double y, double yaw_deg = 0.0) {
  return {{x, y}, std::cos(deg2rad(yaw_deg)), std::sin(deg2rad(yaw_deg))};
}

Tracked ref(int id, Vec2 where) {
  Tracked t;
  t.id = id;
  t.last_seen = where;
  t.visible = true;
  return t;
}

TEST(PfAlignment, ARobotOffTheLineMovesOntoIt) {  // SPEC §2.4
  const Scenario s = short_chain();
  const Params p;
  // robot 0: a sub-nest (child side), robot 1: a RED subgoal (parent side), robot 2: aligning
  World w = make_world(s, p, Mode::kPathFormation, 1,
                       std::vector<Pose>{at(-0.6, 0.0), at(0.6, 0.0), at(0.0, 0.3, 90)});
  w.memory[0].pf.state = PfState::kSubNest;
  w.memory[0].pf.parent = ref(2, {0.0, 0.3});
  w.memory[1].pf.state = PfState::kSubgoal;
  w.memory[1].pf.parent = ref(kGoalEmitter, s.goal);
  PfMemory& m = w.memory[2].pf;
  m.state = PfState::kOpt1;
  m.parent = ref(1, {0.6, 0.0});
  m.child = ref(0, {-0.6, 0.0});
  w.leds = {Led::kBlue, Led::kRed, Led::kMagenta};
  MetricsAccumulator acc;
  acc.begin(3);
  while (m.state == PfState::kOpt1 && w.tick < 400) step(s, p, w, acc);
  EXPECT_EQ(m.state, PfState::kSubNest) << "still " << to_string(m.state) << " at tick " << w.tick;
  // aligned (SPEC §2.4): error angle within e_tol, or within d_tol of the foot on the line
  const Vec2 q = w.positions[2];
  const double e = error_angle(angle_of(w.positions[1] - q), angle_of(w.positions[0] - q));
  const double off_line_cm = 100.0 * std::fabs(q.y);
  EXPECT_TRUE(e <= deg2rad(p.e_tol) + 1e-3 || off_line_cm <= p.d_tol + 0.5)
      << "error angle " << rad2deg(e) << " deg, " << off_line_cm << " cm off the line";
  EXPECT_LT(std::fabs(q.x), 0.30);  // between its references
  // both references stay where they were: stopped robots brake
  EXPECT_LT(dist(w.positions[0], {-0.6, 0.0}), 0.02);
  EXPECT_LT(dist(w.positions[1], {0.6, 0.0}), 0.02);
}

TEST(PfRun, AShortChainFormsAndBothPassesComplete) {
  const Scenario s = short_chain();
  World w;
  const Metrics m = run(Params{}, s, Mode::kPathFormation, 1, {}, &w);
  ASSERT_TRUE(m.success) << "no path in " << m.ticks << " ticks";
  // events in the order of SPEC §2.5
  EXPECT_GT(m.ticks_to_chain, 0);
  EXPECT_LE(m.ticks_to_chain, m.ticks_to_opt1);
  EXPECT_LE(m.ticks_to_opt1, m.ticks_to_form);
  EXPECT_EQ(m.ticks, m.ticks_to_form);  // the run stops at completion
  // the chain: 3.6 m with links of at most R_vis = 1 m needs at least 3 robots
  EXPECT_GE(m.path_robots, 3);
  const double straight_tu = to_tu(dist(s.nest, s.goal));
  EXPECT_GE(m.path_length_tu, straight_tu - 1e-9);
  EXPECT_LE(m.path_length_tu, 1.3 * straight_tu);
  // every link is within camera range and every chain robot finished optimisation 2
  const std::vector<Vec2>& pts = m.final_path.points;
  for (std::size_t i = 1; i < pts.size(); ++i) EXPECT_LE(dist(pts[i - 1], pts[i]), 1.0 + 1e-9);
  for (const int id : m.final_path.robots) {
    EXPECT_EQ(w.memory[static_cast<std::size_t>(id)].pf.state, PfState::kPathDone) << "robot " << id;
  }
  // the chain is the one the world holds: nest-side robot's parents lead to the goal
  EXPECT_EQ(chain_to_goal(w, m.final_path.robots.front()), m.final_path.robots);
}

// ticks_to_goal [R diagnostic]: the first tick a robot stood within 1 m of the goal, as a tick
// observer sees it; before the first subgoal (a robot must reach the goal to form from it)
TEST(PfRun, TicksToGoalIsTheFirstTickARobotCameWithinAMetreOfTheGoal) {
  const Scenario s = short_chain();
  std::int64_t seen = -1;
  const Metrics m = run(Params{}, s, Mode::kPathFormation, 1, [&](const World& w) {
    for (const Vec2& q : w.positions) {
      if (seen < 0 && dist(q, s.goal) <= 1.0) seen = w.tick;
    }
    return false;
  });
  ASSERT_TRUE(m.success);
  ASSERT_GE(seen, 0);
  EXPECT_EQ(m.ticks_to_goal, seen);
  EXPECT_GT(m.ticks_to_goal, 0);  // the robots start at the nest, 3.6 m away
  EXPECT_LT(m.ticks_to_goal, m.ticks_to_chain);
}

// A SUB_NEST robot whose parent finished its optimisation 1 behind an obstacle's corner (out of
// view; the camera's view of a corner need not be mutual) waited for ever for row 11 (env4, 90
// robots, seed 1). It drives toward where it last saw the parent until it sees it (R).
TEST(PfRun, ASubNestLooksForAParentThatMovedOutOfView) {
  const Scenario s = test::small_arena("[[box]]\ncenter = [0.0, 0.6]\nsize = [0.6, 0.8]\n", 3);
  for (const bool seek : {true, false}) {
    Params p;
    p.seek_hidden_reference = seek;
    p.chain_repair = false;  // a parent out of view for T_repair would count as gone (row #19)
    // robot 0: the sub-nest; robot 1: its parent, done, behind the box; robot 2: its child
    World w = make_world(s, p, Mode::kPathFormation, 1,
                         std::vector<Pose>{at(-0.6, 0.7), at(0.5, 0.1), at(-1.2, 0.5)});
    PfMemory& m = w.memory[0].pf;
    m.state = PfState::kSubNest;
    m.parent = ref(1, {0.0, -0.1});  // where it was before its own alignment
    m.child = ref(2, {-1.2, 0.5});
    w.memory[1].pf.state = PfState::kPathDone;
    w.memory[1].pf.parent = ref(kGoalEmitter, s.goal);
    w.memory[2].pf.state = PfState::kSubNest;
    w.memory[2].pf.parent = ref(0, {-0.6, 0.7});
    w.leds = {Led::kBlue, Led::kBrown, Led::kBlue};
    MetricsAccumulator acc;
    acc.begin(3);
    while (m.state == PfState::kSubNest && w.tick < 600) step(s, p, w, acc);
    if (seek) {
      EXPECT_EQ(m.state, PfState::kOpt2) << "still " << to_string(m.state) << " at tick " << w.tick;
      EXPECT_GT(dist(w.positions[0], {-0.6, 0.7}), 0.05) << "found it without moving";
    } else {
      EXPECT_EQ(m.state, PfState::kSubNest);  // SPEC as written: it waits for ever
      EXPECT_LT(dist(w.positions[0], {-0.6, 0.7}), 0.02);
    }
  }
}

// At 20 cm/s most of the 20 robots reach the goal within a few hundred ticks, many from its far
// side; backing off along their own (far-side) way, they all turned RED round the goal and no chain
// reached the nest (docs/CHOICES.md, "Forming a subgoal").
TEST(PfRun, RobotsThatFindTheGoalFromItsFarSideDoNotPileUpRoundIt) {
  const Scenario s = short_chain();
  // both under the trap rule this was measured with (trap_progress 5, a fixed rule then; with
  // 30 cm seed 3 fails either way, its formation broken by recovery robots round the goal)
  Params far_spot;
  far_spot.trap_progress = 5;
  far_spot.form_retries = 0;       // and robots that lose their target turn RECOVERY, as they did then
  far_spot.t_leaf = 0;             // and RED robots round the goal stay there (T_leaf thins that crowd too)
  far_spot.retarget_tip = false;   // and row #5r re-targets by the distance to the nest alone
  far_spot.away_decay = 1.0;       // and every trip explores under the full away field
  far_spot.resume_search = false;  // and from the nest
  test::pf_links_by_trail_slack(far_spot);  // and links laid by trail_slack alone, every one kept
  Params trail_only = far_spot;
  trail_only.backoff_far_spot = false;
  trail_only.trail_slack = 3000;  // stopping anywhere on the way home (3000 cm: no bound)
  int completed = 0;
  int completed_trail_only = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    completed += evaluate(far_spot, s, Mode::kPathFormation, seed).success ? 1 : 0;
    completed_trail_only += evaluate(trail_only, s, Mode::kPathFormation, seed).success ? 1 : 0;
  }
  EXPECT_EQ(completed, 10);
  EXPECT_LE(completed_trail_only, 7);  // seeds 1, 6, 7 and 9 fail without it
}

TEST(PfRun, KeepRunningContinuesPastCompletion) {
  Scenario s = with_max_ticks(short_chain(), 20000);
  const Metrics stop = evaluate(Params{}, s, Mode::kPathFormation, 1);
  ASSERT_TRUE(stop.success);
  s.sim.stop_when_complete = false;
  s = with_max_ticks(s, stop.ticks + 200);
  const Metrics go_on = evaluate(Params{}, s, Mode::kPathFormation, 1);
  EXPECT_EQ(go_on.ticks, stop.ticks + 200);
  EXPECT_EQ(go_on.ticks_to_form, stop.ticks_to_form);  // the same run, measured the same
}

TEST(Determinism, GoldenHashPathFormationShortChain) {
  // update only with a reason, stated in the commit that changes it
  // 8724376 trail_slack 45 cm (was: anywhere on the trail), 1275 -> 1303 ticks
  // 0fea745 trap_progress 30 cm (was 5), 1303 -> 2323 ticks
  // 68e9317 trails that never join two sides of a wall, return_finds (the goal): unchanged
  // ab76562 skip_blocked_crumbs (a robot going home passes over a crumb it cannot reach),
  // 2323 -> 1666 ticks
  // form_retries = 3 in the default (a robot that loses its target goes home, not RECOVERY), 1666 -> 1792
  // align_taper and r_keep_pull removed (the alignment is SPEC §2.4's V = v_align v_max P/|P| + D), -> 1445
  // away_decay = 0.7 in the default (the away field weakens per trip home without a sighting), -> 1436
  // resume_search in the default (a trip after a fruitless one starts where that one ended), -> 1453
  // dead_end_traps 20 (an edge following turns back only when T_follow runs out), -> 1516
  // anywhere_after_edge_pf and chain_bypass_pf in the default (path formation's robots stop anywhere
  // on a way that went round an edge; a link that sees its parent's parent skips its parent), -> 1521
  constexpr std::uint64_t kExpected = 0x3cf371dc33b021cdULL;  // a complete run: 1521 ticks
  const Metrics m = evaluate(Params{}, short_chain(), Mode::kPathFormation, 1);
  EXPECT_EQ(m.state_hash, kExpected) << "actual state_hash 0x" << to_hex(m.state_hash) << " (ticks "
                                     << m.ticks << ")";
}

}  // namespace
}  // namespace swarmpath::sim
