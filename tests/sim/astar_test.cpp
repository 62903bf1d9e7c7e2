// SPDX-License-Identifier: MIT
// The A* baseline (SPEC §4.5) reproduces the SPEC §3.3 reference lengths of the eight arenas.
#include "sim/astar.hpp"

#include <gtest/gtest.h>

#include "sim/config_error.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

struct Expected {
  int env;
  double astar8_tu;  // SPEC §3.3 / §8: A*-8, 1 cm grid, 8.5 cm inflation
  double astar4_tu;  // SPEC §3.3 reference table, A*-4 column
  double euclid_tu;
};

void PrintTo(const Expected& e, std::ostream* os) { *os << "env" << e.env; }

class AStarPaperEnv : public ::testing::TestWithParam<Expected> {};

TEST_P(AStarPaperEnv, MatchesTheSpecReferenceLengths) {
  const Expected e = GetParam();
  const Scenario s = load_scenario(test::paper_env(e.env));
  const AStarResult a8 = astar(s, {Connectivity::kEight});
  const AStarResult a4 = astar(s, {Connectivity::kFour});
  ASSERT_TRUE(a8.found);
  ASSERT_TRUE(a4.found);
  EXPECT_NEAR(to_tu(a8.length_m), e.astar8_tu, 0.2) << "env" << e.env;
  EXPECT_NEAR(to_tu(a4.length_m), e.astar4_tu, 0.2) << "env" << e.env;
  // a grid path is never shorter than the straight line, and 4-connected never shorter than 8
  EXPECT_GE(to_tu(a8.length_m) + 0.02, e.euclid_tu);
  EXPECT_GE(a4.length_m, a8.length_m);
  // the path runs from the nest's cell to the goal's cell
  EXPECT_LT(dist(a8.path.front(), s.nest), 0.01);
  EXPECT_LT(dist(a8.path.back(), s.goal), 0.01);
}

INSTANTIATE_TEST_SUITE_P(Spec, AStarPaperEnv,
                         ::testing::Values(Expected{1, 100.0, 100.0, 100.0}, Expected{2, 112.7, 136.1, 104.2},
                                           Expected{3, 132.9, 160.4, 122.8}, Expected{4, 144.3, 164.6, 130.0},
                                           Expected{5, 158.9, 185.6, 143.2}, Expected{6, 172.4, 190.9, 159.4},
                                           Expected{7, 143.0, 175.6, 120.0},
                                           Expected{8, 191.3, 244.0, 140.0}),
                         [](const auto& p) { return "env" + std::to_string(p.param.env); });

TEST(AStar, PathAvoidsTheInflatedObstacles) {
  const Scenario s = load_scenario(test::paper_env(4));
  const AStarResult a8 = astar(s);
  const auto shapes = obstacle_shapes(s);
  for (std::size_t i = 0; i + 1 < a8.path.size(); ++i) {
    for (int k = 0; k <= 20; ++k) {  // sample each straight run
      const Vec2 p = a8.path[i] + (k / 20.0) * (a8.path[i + 1] - a8.path[i]);
      for (const Shape& sh : shapes) EXPECT_GT(signed_distance(sh, p), 0.085 - 0.01);
    }
  }
}

TEST(AStar, NoPathWhenTheGoalIsWalledIn) {
  // built in code: a scenario file like this is refused at load (the goal cannot be reached)
  Scenario s = test::small_arena();
  s.boxes = {{{2.0, 0.6}, {1.2, 0.2}, 0.0},
             {{2.0, -0.6}, {1.2, 0.2}, 0.0},
             {{1.5, 0.0}, {0.2, 1.2}, 0.0},
             {{2.5, 0.0}, {0.2, 1.2}, 0.0}};
  EXPECT_FALSE(astar(s).found);
  // path / A* would be undefined: the baseline is a bad input naming the file
  try {
    (void)astar8_baseline_tu(s, "walled.toml");
    ADD_FAILURE() << "a baseline without a path";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "walled.toml");
    EXPECT_NE(std::string(e.what()).find(kNoAStarPath), std::string::npos) << e.what();
  }
}

TEST(AStar, TheBaselineIsTheEightConnectedLengthInTableUnits) {
  const Scenario s = load_scenario(test::paper_env(4));
  EXPECT_EQ(astar8_baseline_tu(s, s.file), to_tu(astar(s, {Connectivity::kEight}).length_m));
}

}  // namespace
}  // namespace swarmpath::sim
