// SPDX-License-Identifier: MIT
// Hypervolume (2D sweep, 3D slices) against hand-computed volumes and a grid count; non_dominated.
#include "evolve/optim/hypervolume.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "sim/rng.hpp"

namespace swarmpath::evolve {
namespace {

TEST(Hypervolume, TwoDimensionalHandCases) {
  const Vector ref = {1.0, 1.0};
  EXPECT_EQ(hypervolume({}, ref), 0.0);
  EXPECT_DOUBLE_EQ(hypervolume({{0.5, 0.25}}, ref), 0.5 * 0.75);
  // two rectangles 0.8 x 0.4 and 0.5 x 0.7 overlapping in 0.5 x 0.4: 0.32 + 0.35 - 0.20
  const std::vector<Vector> two = {{0.2, 0.6}, {0.5, 0.3}};
  EXPECT_DOUBLE_EQ(hypervolume(two, ref), 0.47);
  // a dominated point, a duplicate and points not strictly inside the reference add nothing
  auto more = two;
  more.push_back({0.6, 0.7});
  more.push_back({0.5, 0.3});
  more.push_back({1.0, 0.1});   // on the reference in f1
  more.push_back({1.5, -3.0});  // outside in f1
  more.push_back({NAN, 0.0});
  EXPECT_DOUBLE_EQ(hypervolume(more, ref), 0.47);
  EXPECT_EQ(hypervolume({{1.0, 0.1}, {0.2, 1.0}}, ref), 0.0);
}

TEST(Hypervolume, ThreeDimensionalHandCases) {
  const Vector ref = {1.0, 1.0, 1.0};
  EXPECT_DOUBLE_EQ(hypervolume({{0.5, 0.5, 0.5}}, ref), 0.125);
  // inclusion-exclusion, each box [p, ref], an intersection the box of the coordinate-wise max:
  //   A = (0.2, 0.6, 0.4): 0.8 * 0.4 * 0.6 = 0.192    A^B = (0.5, 0.6, 0.4): 0.5 * 0.4 * 0.6 = 0.120
  //   B = (0.5, 0.3, 0.1): 0.5 * 0.7 * 0.9 = 0.315    A^C = (0.7, 0.7, 0.4): 0.3 * 0.3 * 0.6 = 0.054
  //   C = (0.7, 0.7, 0.0): 0.3 * 0.3 * 1.0 = 0.090    B^C = (0.7, 0.7, 0.1): 0.3 * 0.3 * 0.9 = 0.081
  //   A^B^C = (0.7, 0.7, 0.4): 0.054
  //   0.192 + 0.315 + 0.090 - 0.120 - 0.054 - 0.081 + 0.054 = 0.396 (a Monte Carlo check gave 0.3959)
  const std::vector<Vector> abc = {{0.2, 0.6, 0.4}, {0.5, 0.3, 0.1}, {0.7, 0.7, 0.0}};
  EXPECT_NEAR(hypervolume(abc, ref), 0.396, 1e-12);
  auto more = abc;
  more.push_back({0.8, 0.8, 0.5});  // dominated by A
  more.push_back({0.1, 0.1, 1.0});  // on the reference in f3
  more.push_back({0.1, 2.0, 0.1});  // outside in f2
  EXPECT_NEAR(hypervolume(more, ref), 0.396, 1e-12);
}

TEST(Hypervolume, ThreeDimensionsWithAConstantThirdObjectiveIsAreaTimesDepth) {
  sim::Rng rng(5);
  std::vector<Vector> flat;
  std::vector<Vector> deep;
  for (int i = 0; i < 30; ++i) {
    const double a = rng.uniform(0.0, 1.2);
    const double b = rng.uniform(0.0, 1.2);
    flat.push_back({a, b});
    deep.push_back({a, b, 0.25});
  }
  const double area = hypervolume(flat, {1.1, 1.0});
  ASSERT_GT(area, 0.5);
  EXPECT_NEAR(hypervolume(deep, {1.1, 1.0, 2.0}), area * 1.75, 1e-12);
}

/// The hypervolume of points on the grid {0, 0.1, ..., 1}^m with reference (1, ..., 1), by
/// counting the dominated cells of side 0.1 (each cell is dominated or not as a whole).
double grid_count(const std::vector<Vector>& points, std::size_t m) {
  long cells = 0;
  const int n = m == 3 ? 1000 : 100;
  for (int c = 0; c < n; ++c) {
    const int idx[3] = {c % 10, (c / 10) % 10, c / 100};
    for (const auto& p : points) {
      bool dominated = true;
      for (std::size_t k = 0; k < m; ++k) dominated = dominated && std::lround(p[k] * 10.0) <= idx[k];
      if (dominated) {
        ++cells;
        break;
      }
    }
  }
  return static_cast<double>(cells) * std::pow(0.1, static_cast<double>(m));
}

TEST(Hypervolume, AgreesWithACellCountOnRandomGridPoints) {
  sim::Rng rng(11);
  for (const std::size_t m : {std::size_t{2}, std::size_t{3}}) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<Vector> points(1 + rng.below(12), Vector(m));
      for (auto& p : points) {
        for (double& v : p) v = static_cast<double>(rng.below(11)) / 10.0;  // 1.0: on the reference
      }
      EXPECT_NEAR(hypervolume(points, Vector(m, 1.0)), grid_count(points, m), 1e-12)
          << m << " objectives, trial " << trial;
    }
  }
}

TEST(Hypervolume, RejectsOtherDimensionsAndMismatchedPoints) {
  EXPECT_THROW(hypervolume({{0.5}}, {1.0}), std::invalid_argument);
  EXPECT_THROW(hypervolume({{0.5, 0.5, 0.5, 0.5}}, {1.0, 1.0, 1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(hypervolume({{0.5, 0.5}, {0.5, 0.5, 0.5}}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(hypervolume({{0.5, 0.5}}, {1.0, INFINITY}), std::invalid_argument);
  EXPECT_THROW(non_dominated({{0.5, 0.5}, {0.5}}), std::invalid_argument);
}

TEST(NonDominated, KeepsTheParetoSetAndEqualPoints) {
  const std::vector<Vector> points = {{1, 4}, {2, 2}, {3, 3}, {4, 1}, {2, 2}, {1, 5}, {0.5, 6}};
  // (3,3) is dominated by (2,2); (1,5) by (1,4); the two (2,2) do not dominate each other
  EXPECT_EQ(non_dominated(points), (std::vector<std::size_t>{0, 1, 3, 4, 6}));
  EXPECT_TRUE(non_dominated({}).empty());
  EXPECT_TRUE(dominates({1, 2}, {1, 3}));
  EXPECT_FALSE(dominates({1, 3}, {1, 3}));
  EXPECT_FALSE(dominates({0, 4}, {1, 3}));
}

}  // namespace
}  // namespace swarmpath::evolve
