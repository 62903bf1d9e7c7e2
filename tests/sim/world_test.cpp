// SPDX-License-Identifier: MIT
// Deployment (SPEC §3.3) and simple run-level properties of the simulator.
#include <cmath>

#include <gtest/gtest.h>

#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

TEST(Deployment, RobotsStartInsideTheRegionApartAndClearOfObstacles) {
  for (int k : {4, 7}) {
    const Scenario s = load_scenario(test::paper_env(k));
    const auto shapes = obstacle_shapes(s);
    const std::vector<Pose> poses = deploy(s, shapes, 11);
    ASSERT_EQ(poses.size(), 100u);
    const Aabb region = s.deployment.bounds();
    for (std::size_t i = 0; i < poses.size(); ++i) {
      EXPECT_TRUE(region.contains(poses[i].p));
      for (const Shape& sh : shapes) EXPECT_GE(signed_distance(sh, poses[i].p), kRobotRadius);
      for (std::size_t j = 0; j < i; ++j) EXPECT_GE(dist(poses[i].p, poses[j].p), s.min_spacing);
    }
  }
}

TEST(Deployment, SameSeedSamePlacesOtherSeedOtherPlaces) {
  const Scenario s = load_scenario(test::paper_env(1));
  const auto shapes = obstacle_shapes(s);
  const auto a = deploy(s, shapes, 5);
  const auto b = deploy(s, shapes, 5);
  const auto c = deploy(s, shapes, 6);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].p, b[i].p);
    EXPECT_EQ(a[i].c, b[i].c);
  }
  EXPECT_NE(a[0].p, c[0].p);
}

TEST(Deployment, DenseRegionIsFilledOrRejectedCleanly) {
  // right at the capacity bound the sampler still fills the region
  const Scenario s = test::small_arena("", 14);
  EXPECT_EQ(deploy(s, obstacle_shapes(s), 1).size(), 14u);
}

class DiffusionRun : public ::testing::TestWithParam<std::uint64_t> {};

// properties over seeds: robots stay in the arena, no NaN, they move, metrics are sane
TEST_P(DiffusionRun, RobotsStayInsideTheArenaAndMove) {
  Scenario s = with_max_ticks(load_scenario(test::paper_env(7)), 1500);
  World w = make_world(s, Params{}, Mode::kDiffusion, GetParam());
  MetricsAccumulator m;
  m.begin(w.robot_count());
  const Aabb inside = {s.arena_bounds().lo + Vec2{0.1, 0.1}, s.arena_bounds().hi - Vec2{0.1, 0.1}};
  const auto shapes = obstacle_shapes(s);
  for (int t = 0; t < 1500; ++t) {
    step(s, Params{}, w, m);
    if (t % 100 != 99) continue;
    for (const Pose& p : w.poses) {
      ASSERT_TRUE(std::isfinite(p.p.x) && std::isfinite(p.p.y));
      ASSERT_TRUE(inside.contains(p.p)) << "robot left the arena at tick " << w.tick;
      for (const Shape& sh : shapes) ASSERT_GT(signed_distance(sh, p.p), kRobotRadius - 0.02);
    }
  }
  const Metrics r = m.finish(w.tick, s.sim.dt(), state_hash(w));
  const double v_max = Params{}.v_max;
  EXPECT_GT(r.mean_speed_cm_s, 0.3 * v_max);  // a random walk at v_max, slowed by collisions
  EXPECT_LE(r.mean_speed_cm_s, v_max + 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Seeds, DiffusionRun, ::testing::Values(1u, 2u, 3u));

}  // namespace
}  // namespace swarmpath::sim
