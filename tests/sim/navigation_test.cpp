// SPDX-License-Identifier: MIT
// The navigator's trap rule [R]: a robot against an obstacle that has not gained trap_progress
// toward its point for T_trap ticks starts following the obstacle's edge. Robots queueing at a
// wall creep a few cm at a time as they jostle; such creeping must not keep resetting the count.
#include "sim/controllers/navigation.hpp"

#include <gtest/gtest.h>

namespace swarmpath::sim {
namespace {

// a robot with a wall straight ahead (the front proximity sensor reads)
Percept against_a_wall() {
  Percept in;
  in.pose = Pose{{0.0, 0.0}, 1.0, 0.0};
  in.proximity[0] = 0.6;
  return in;
}

// ticks until nav_update says "follow the edge", for a robot that creeps `creep_cm` per tick
// toward its point (-1 if it never does within `limit` ticks)
int ticks_until_following(const Params& p, double creep_cm, int limit) {
  NavMemory nav;
  Rng rng(1);
  const Percept in = against_a_wall();
  double progress = -500.0;  // 5 m from the point
  for (int t = 1; t <= limit; ++t) {
    progress += creep_cm;
    if (nav_update(nav, p, rng, progress, in, Vec2{1.0, 0.0})) return t;
  }
  return -1;
}

TEST(Navigator, CreepingLessThanTrapProgressPerTTrapStillCountsAsTrapped) {
  Params p;  // T_trap 100, trap_progress 30 cm
  // 0.25 cm a tick: 25 cm in T_trap ticks, less than trap_progress
  EXPECT_EQ(ticks_until_following(p, 0.25, 1000), static_cast<int>(p.t_trap) + 1);
  // standing still: the same
  EXPECT_EQ(ticks_until_following(p, 0.0, 1000), static_cast<int>(p.t_trap) + 1);
  // moving on (1 cm a tick, 100 cm per T_trap): never trapped
  EXPECT_EQ(ticks_until_following(p, 1.0, 1000), -1);
}

TEST(Navigator, WithTheOldFiveCmThresholdACreepingQueueNeverFollowsTheEdge) {
  Params p;
  p.trap_progress = 5;  // before stop 22
  EXPECT_EQ(ticks_until_following(p, 0.25, 1000), -1);
  EXPECT_EQ(ticks_until_following(p, 0.0, 1000), static_cast<int>(p.t_trap) + 1);
}

}  // namespace
}  // namespace swarmpath::sim
