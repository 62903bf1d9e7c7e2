// SPDX-License-Identifier: MIT
// The vector-to-wheels mapping with hard/soft/no-turn hysteresis (SPEC §1.2).
#include "sim/drive.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace swarmpath::sim {
namespace {

Vec2 at(double deg, double len = 10.0) { return len * unit(deg2rad(deg)); }

TEST(Drive, StraightAheadIsNoTurnAtMinOfLengthAndVmax) {
  const Params p;
  TurnMode m = TurnMode::kNone;
  WheelSpeeds w = wheels_from_vector(at(0.0, 6.0), p, m);
  EXPECT_EQ(m, TurnMode::kNone);
  EXPECT_DOUBLE_EQ(w.left_cm_s, 6.0);
  EXPECT_DOUBLE_EQ(w.right_cm_s, 6.0);
  w = wheels_from_vector(at(0.0, 25.0), p, m);  // b = min(|V|, v_max), v_max = 20 < 25
  EXPECT_DOUBLE_EQ(w.left_cm_s, p.v_max);
  EXPECT_DOUBLE_EQ(w.right_cm_s, p.v_max);
}

TEST(Drive, SoftTurnSpeedsFollowTheFormula) {
  const Params p;
  TurnMode m = TurnMode::kNone;
  const WheelSpeeds w = wheels_from_vector(at(45.0), p, m);  // NONE -> SOFT (|a| > theta_none)
  EXPECT_EQ(m, TurnMode::kSoft);
  const double f = (90.0 - 45.0) / 90.0;
  EXPECT_NEAR(w.left_cm_s, 10.0 * f, 1e-12);  // left is inner: turning left
  EXPECT_NEAR(w.right_cm_s, 10.0 * (2.0 - f), 1e-12);
  TurnMode m2 = TurnMode::kNone;
  const WheelSpeeds r = wheels_from_vector(at(-45.0), p, m2);  // mirrored
  EXPECT_NEAR(r.right_cm_s, 10.0 * f, 1e-12);
  EXPECT_NEAR(r.left_cm_s, 10.0 * (2.0 - f), 1e-12);
}

TEST(Drive, HardTurnSpinsInPlaceTowardTheVector) {
  const Params p;
  TurnMode m = TurnMode::kNone;
  WheelSpeeds w = wheels_from_vector(at(120.0), p, m);
  EXPECT_EQ(m, TurnMode::kHard);
  EXPECT_DOUBLE_EQ(w.left_cm_s, -p.v_max);
  EXPECT_DOUBLE_EQ(w.right_cm_s, p.v_max);
  w = wheels_from_vector(at(-150.0, 2.0), p, m);  // hard turn uses v_max whatever |V|
  EXPECT_DOUBLE_EQ(w.left_cm_s, p.v_max);
  EXPECT_DOUBLE_EQ(w.right_cm_s, -p.v_max);
}

TEST(Drive, HysteresisKeepsTheModeBetweenThresholds) {
  const Params p;  // hard 90, soft 70, none 10
  TurnMode m = TurnMode::kHard;
  wheels_from_vector(at(80.0), p, m);  // HARD stays until |a| <= theta_soft
  EXPECT_EQ(m, TurnMode::kHard);
  wheels_from_vector(at(70.0), p, m);
  EXPECT_EQ(m, TurnMode::kSoft);
  wheels_from_vector(at(85.0), p, m);  // SOFT stays until |a| > theta_hard
  EXPECT_EQ(m, TurnMode::kSoft);
  wheels_from_vector(at(5.0), p, m);  // SOFT -> NONE
  EXPECT_EQ(m, TurnMode::kNone);
  wheels_from_vector(at(8.0), p, m);  // NONE stays within theta_none
  EXPECT_EQ(m, TurnMode::kNone);
  m = TurnMode::kHard;
  wheels_from_vector(at(3.0), p, m);  // cascade: HARD -> SOFT -> NONE in one call
  EXPECT_EQ(m, TurnMode::kNone);
}

}  // namespace
}  // namespace swarmpath::sim
