// SPDX-License-Identifier: MIT
// view --census's stalls (app/stalls.hpp): robots that stood within 25 cm for 2 000 ticks or more in
// a state in which they are meant to move, found in a recording's frames.
#include "app/stalls.hpp"

#include <gtest/gtest.h>

#include "app/census.hpp"

namespace swarmpath::app {
namespace {

constexpr int kRobots = 4;
constexpr int kFrames = 40;  // every 100 ticks: ticks 0 - 3 900

// robot 0 goes home (1 m a frame), stands at (5, 0) within 10 cm from tick 1 000 to 3 500, then
// goes on; robot 1 is a subgoal and robot 2 a robot told to rest, both standing all the run;
// robot 3 explores, creeping 5 cm a frame (past 25 cm within every 2 000 ticks)
sim::Recording recording() {
  sim::Recording r;
  r.robots = kRobots;
  r.every = 100;
  r.ticks = 100 * (kFrames - 1);
  r.origin = {-20.0, -20.0};
  r.nest = {0.0, 0.0};
  r.state_names = {{0, "path_formation/return_to_nest"},
                   {1, "path_formation/subgoal"},
                   {2, "resting_task/exploring"},
                   {3, "path_formation/exploring"}};
  for (int f = 0; f < kFrames; ++f) {
    r.frame_ticks.push_back(100 * f);
    const double home = f < 10 ? 15.0 - f : f <= 35 ? 5.0 - (f % 2 == 0 ? 0.0 : 0.1) : 5.0 - (f - 35);
    const sim::Vec2 at[kRobots] = {{home, 0.0}, {2.0, 2.0}, {-1.0, 0.5}, {-3.0 + 0.05 * f, -3.0}};
    for (int i = 0; i < kRobots; ++i) {
      r.qx.push_back(sim::quantise(at[i].x, r.origin.x, r.quantum));
      r.qy.push_back(sim::quantise(at[i].y, r.origin.y, r.quantum));
      r.heading.push_back(0);
      r.led.push_back(0);
      r.state.push_back(static_cast<std::uint8_t>(i));
      r.parent.push_back(-1);
      r.child.push_back(-1);
    }
  }
  return r;
}

TEST(Stalls, ARobotStandingWhereItShouldMoveIsAStallAndAStandingLinkIsNot) {
  const sim::Recording r = recording();
  const std::vector<Stall> stalls = find_stalls(r);
  ASSERT_EQ(stalls.size(), 1u);
  EXPECT_EQ(stalls[0].robot, 0);
  EXPECT_EQ(stalls[0].from, 1000);
  EXPECT_EQ(stalls[0].ticks, 2500);  // its frames at ticks 1 000 - 3 500
  const nlohmann::ordered_json j = census(r)["stalls"];
  EXPECT_EQ(j["count"], 1);
  EXPECT_EQ(j["robot_ticks"], 2500);
  EXPECT_EQ(j["by_state"]["path_formation/return_to_nest"]["count"], 1);
  ASSERT_EQ(j["longest"].size(), 1u);
  EXPECT_EQ(j["longest"][0]["state"], "path_formation/return_to_nest");
  EXPECT_DOUBLE_EQ(j["longest"][0]["from_nest_m"].get<double>(), 5.0);
}

}  // namespace
}  // namespace swarmpath::app
