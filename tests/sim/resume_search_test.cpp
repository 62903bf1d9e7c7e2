// SPDX-License-Identifier: MIT
// resume_search [R] (docs/detours.md, rows 2 and #4): a trip that ends back home without a sighting
// of the goal or the chain keeps its way, and the robot's next trip, with no sighting to travel to,
// first travels along that way to where the trip ended, then explores from there.
#include <vector>

#include <gtest/gtest.h>

#include "sim/controller.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

struct Frontiers {
  int trips = 0;       ///< trips that began by travelling to a frontier
  int arrived = 0;     ///< ... whose travel ended within 0.5 m of it
  int mismatches = 0;  ///< frontiers more than 0.3 m from where the robot's last trip turned home
};

// far_door (a wall with one doorway far off the line), 50 robots, path formation, seed 1, 8 000
// ticks: robots come home from several trips that saw nothing
Frontiers watch_frontiers(const Params& p) {
  const Scenario s = load_scenario(test::source_path("tests/data/far_door.toml"));
  Frontiers out;
  std::vector<Vec2> turned_home;  // where each robot's last trip turned home
  std::vector<PfState> state;
  std::vector<ExploreLeg> leg;
  run(
      p, s, Mode::kPathFormation, 1,
      [&](const World& w) {
        const std::size_t n = w.memory.size();
        if (state.empty()) {
          turned_home.assign(n, Vec2{});
          state.assign(n, PfState::kExploring);
          leg.assign(n, ExploreLeg::kWalk);
        }
        for (std::size_t i = 0; i < n; ++i) {
          const PfMemory& m = w.memory[i].pf;
          const Vec2 at = w.poses[i].p;
          if (m.state == PfState::kReturnToNest && state[i] == PfState::kExploring) turned_home[i] = at;
          if (m.explore_leg == ExploreLeg::kToFrontier && leg[i] != ExploreLeg::kToFrontier) {
            ++out.trips;
            if (dist(m.frontier, turned_home[i]) > 0.3) ++out.mismatches;
          }
          if (leg[i] == ExploreLeg::kToFrontier && m.explore_leg == ExploreLeg::kWalk &&
              dist(at, m.frontier) < 0.5)
            ++out.arrived;
          state[i] = m.state;
          leg[i] = m.explore_leg;
        }
        return w.tick >= 8000;
      },
      nullptr);
  return out;
}

TEST(ResumeSearch, ATripAfterAFruitlessOneTravelsToWhereThatOneTurnedHome) {
  const Params on;
  ASSERT_TRUE(on.resume_search);  // in the default
  Params off = on;
  off.resume_search = false;
  const Frontiers with = watch_frontiers(on);
  EXPECT_GE(with.trips, 10);
  EXPECT_EQ(with.mismatches, 0);
  EXPECT_GT(2 * with.arrived, with.trips);  // most travels along the kept way get there
  const Frontiers without = watch_frontiers(off);
  EXPECT_EQ(without.trips, 0);
}

// tests/data/rooms_1.toml (the training arena rooms-1: the goal's room beside the nest's with no door
// between them, the way round through two other rooms), 100 robots, seed 21, path formation, the
// first 12 000 ticks: every trip explored from the nest reaches no robot within R_vis of the goal;
// trips that resume where the last one turned home do (docs/detours.md: 26 611 against 9 587 ticks)
TEST(ResumeSearch, TheGoalBehindTwoRoomsIsReachedWhenTripsResume) {
  Params on;
  test::hasty_along_walls(on);  // as measured
  Params off = on;
  off.resume_search = false;
  const Scenario s = with_max_ticks(load_scenario(test::source_path("tests/data/rooms_1.toml")), 12000);
  const Metrics without = evaluate(off, s, Mode::kPathFormation, 21);
  const Metrics with = evaluate(on, s, Mode::kPathFormation, 21);
  EXPECT_EQ(without.ticks_to_goal, -1);
  EXPECT_GT(with.ticks_to_goal, 0);
}

}  // namespace
}  // namespace swarmpath::sim
