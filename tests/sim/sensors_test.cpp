// SPDX-License-Identifier: MIT
// Sensor geometry (SPEC §1.3): camera line of sight and range, proximity readings at known
// distances, range-and-bearing range, line of sight and one-tick latency.
#include <cmath>

#include <gtest/gtest.h>

#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

Pose pose_at(double x, double y, double yaw_deg = 0.0) {
  const double a = deg2rad(yaw_deg);
  return {{x, y}, std::cos(a), std::sin(a)};
}

World world_at(const Scenario& s, const std::vector<Pose>& poses, const Params& p = {}) {
  return make_world(s, p, Mode::kDiffusion, 1, poses);
}

std::vector<Blob> camera(const Scenario& s, const World& w, int id, const Params& p = {}) {
  std::vector<Blob> out;
  sense_camera(sensor_view(s, p, w), id, out);
  return out;
}

const Blob* find_emitter(const std::vector<Blob>& blobs, int emitter) {
  for (const Blob& b : blobs) {
    if (b.emitter == emitter) return &b;
  }
  return nullptr;
}

// a thin wall across x = 0.4 from y = -0.5 to 0.5, and two robots either side of it
const char* kWall = "[[box]]\ncenter = [0.4, 0.0]\nsize = [0.05, 1.0]\n";

TEST(Camera, RobotInTheOpenIsSeenWithBearingAndDistance) {
  const Scenario s = test::small_arena();
  const World w = world_at(s, {pose_at(0.0, 0.0), pose_at(0.8, 0.0), pose_at(0.0, 0.5)});
  const auto blobs = camera(s, w, 0);
  const Blob* ahead = find_emitter(blobs, 1);
  ASSERT_NE(ahead, nullptr);
  EXPECT_EQ(ahead->color, Led::kGreen);
  EXPECT_NEAR(ahead->distance_cm, 80.0, 1e-4);
  EXPECT_NEAR(ahead->bearing(), 0.0, 1e-6);
  const Blob* left = find_emitter(blobs, 2);
  ASSERT_NE(left, nullptr);
  EXPECT_NEAR(left->bearing(), kPi / 2, 1e-6);  // bearing counter-clockwise from the heading
}

TEST(Camera, RobotBehindAWallIsNotSeen) {
  const Scenario s = test::small_arena(kWall);
  const World w = world_at(s, {pose_at(0.0, 0.0), pose_at(0.8, 0.0), pose_at(0.3, 0.9)});
  const auto blobs = camera(s, w, 0);
  EXPECT_EQ(find_emitter(blobs, 1), nullptr);  // the wall cuts the line of sight
  EXPECT_NE(find_emitter(blobs, 2), nullptr);  // past the wall's end: seen
}

// led_ring [R]: a box's corner hides the robot's centre but not the 9 cm ring's near tangent point
TEST(Camera, ARobotIsSeenByItsLedRingUnlessThatIsSwitchedOff) {
  const Scenario s = test::small_arena("[[box]]\ncenter = [0.45, -0.085]\nsize = [0.05, 0.23]\n");
  const World w = world_at(s, {pose_at(0.0, 0.0), pose_at(0.9, 0.0)});
  EXPECT_NE(find_emitter(camera(s, w, 0), 1), nullptr);
  Params centre_only;
  centre_only.led_ring = false;
  EXPECT_EQ(find_emitter(camera(s, w, 0, centre_only), 1), nullptr);
}

TEST(Camera, RangeIsRvisAndDarkLedsAreInvisible) {
  const Scenario s = test::small_arena();
  World w = world_at(s, {pose_at(0.0, 0.0), pose_at(0.99, 0.0), pose_at(0.0, -1.01), pose_at(-0.5, 0.0)});
  w.leds[3] = Led::kBlack;  // resting: LEDs off
  const auto blobs = camera(s, w, 0);
  EXPECT_NE(find_emitter(blobs, 1), nullptr);
  EXPECT_EQ(find_emitter(blobs, 2), nullptr);  // beyond R_vis = 100 cm
  EXPECT_EQ(find_emitter(blobs, 3), nullptr);
  Params wide;
  wide.r_vis = 150;
  World w2 = world_at(s, {pose_at(0.0, 0.0), pose_at(0.99, 0.0), pose_at(0.0, -1.01)}, wide);
  EXPECT_NE(find_emitter(camera(s, w2, 0, wide), 2), nullptr);
}

TEST(Camera, BeaconsAreSeenUnlessBlocked) {
  // nest at (-2, 0), goal at (2, 0)
  const Scenario s = test::small_arena("[[box]]\ncenter = [1.5, 0.0]\nsize = [0.05, 1.0]\n");
  const World w = world_at(s, {pose_at(-1.5, 0.0, 180.0), pose_at(1.2, 0.0)});
  const auto near_nest = camera(s, w, 0);
  const Blob* nest = find_emitter(near_nest, kNestEmitter);
  ASSERT_NE(nest, nullptr);
  EXPECT_EQ(nest->color, Led::kBlue);
  EXPECT_NEAR(nest->distance_cm, 50.0, 1e-4);
  EXPECT_NEAR(nest->bearing(), 0.0, 1e-6);                          // facing the nest
  EXPECT_EQ(find_emitter(camera(s, w, 1), kGoalEmitter), nullptr);  // goal 80 cm away behind the box
}

TEST(Camera, RobotsOccludeOnlyWithTheFlag) {
  Scenario s = test::small_arena();
  const std::vector<Pose> line = {pose_at(0.0, 0.0), pose_at(0.4, 0.0), pose_at(0.8, 0.0)};
  EXPECT_NE(find_emitter(camera(s, world_at(s, line), 0), 2), nullptr);
  s.sim.occlude_by_robots = true;
  EXPECT_EQ(find_emitter(camera(s, world_at(s, line), 0), 2), nullptr);
  EXPECT_NE(find_emitter(camera(s, world_at(s, line), 0), 1), nullptr);
}

// proximity against a box face at x = 1.9, the robot facing it (SPEC §1.3 response curve)
TEST(Proximity, ReadingsAgainstAWallAtKnownDistances) {
  const Scenario s = test::small_arena("[[box]]\ncenter = [2.0, 1.2]\nsize = [0.2, 1.0]\n");
  for (const double gap : {0.005, 0.02, 0.05, 0.09, 0.12}) {
    const World w = world_at(s, {pose_at(1.9 - kRobotRadius - gap, 1.2)});
    std::array<double, kProximityCount> r{};
    sense_proximity(sensor_view(s, Params{}, w), 0, r);
    // sensors 0 (+7.5 deg) and 23 (-7.5 deg) start on the body circle, R cos(7.5 deg) ahead of
    // the centre, and meet the face after (gap + R - R cos(7.5 deg)) / cos(7.5 deg)
    const double c = std::cos(deg2rad(7.5));
    const double along = (gap + kRobotRadius - kRobotRadius * c) / c;
    const double expected = along <= kProximityRange ? proximity_response(along) : 0.0;
    EXPECT_NEAR(r[0], expected, 1e-5) << "gap " << gap;  // positions are Box2D floats
    EXPECT_NEAR(r[23], expected, 1e-5) << "gap " << gap;
    // sensors facing backwards see nothing
    EXPECT_EQ(r[12], 0.0);
    EXPECT_EQ(r[11], 0.0);
  }
  EXPECT_NEAR(proximity_response(0.1), 0.1, 0.001);  // about 0.1 at 10 cm
  EXPECT_EQ(proximity_response(0.005), 1.0);
}

TEST(Proximity, AnotherRobotIsSeenByTheSensorsFacingIt) {
  const Scenario s = test::small_arena();
  // robot 1 straight to the left (+90 deg), edge to edge 5 cm
  const World w = world_at(s, {pose_at(0.0, 0.0), pose_at(0.0, 2 * kRobotRadius + 0.05)});
  std::array<double, kProximityCount> r{};
  sense_proximity(sensor_view(s, Params{}, w), 0, r);
  // sensors 5 (82.5 deg) and 6 (97.5 deg) straddle the direction
  EXPECT_GT(r[5], 0.15);
  EXPECT_NEAR(r[5], r[6], 1e-9);
  EXPECT_EQ(r[17], 0.0);
  EXPECT_EQ(r[0], 0.0);
}

TEST(RangeAndBearing, DeliveredNextTickWithinRangeAndLineOfSight) {
  const Scenario s = test::small_arena("[[box]]\ncenter = [0.0, -1.0]\nsize = [1.0, 0.05]\n");
  // 0 sends; 1 is 2.5 m away; 2 is 3.6 m away (out of range); 3 is 1.8 m away behind the box
  World w = world_at(s, {pose_at(-1.0, 0.0), pose_at(1.5, 0.0, 90.0), pose_at(2.3, 1.5), pose_at(0.0, -1.5)});
  Params p;
  MetricsAccumulator m;
  m.begin(w.robot_count());
  w.needs.rab = true;
  // tick 0: robot 0 asks to send; nothing is heard in the same tick
  sense_all(s, p, w);
  for (const Percept& in : w.percepts) EXPECT_TRUE(in.rab.empty());
  control_all(p, w);
  w.commands[0].rab_send = true;
  w.commands[0].rab = {7, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  act_all(w);
  integrate(s, w, m);
  // tick 1: heard by robot 1 only
  sense_all(s, p, w);
  ASSERT_EQ(w.percepts[1].rab.size(), 1u);
  const RabMessage& msg = w.percepts[1].rab[0];
  EXPECT_EQ(msg.sender, 0);
  EXPECT_EQ(msg.data[0], 7);
  EXPECT_EQ(msg.data[9], 9);
  EXPECT_NEAR(msg.range_cm, 100.0 * dist(w.poses[0].p, w.poses[1].p), 1e-9);
  EXPECT_NEAR(msg.bearing(), kPi / 2, 0.05);  // robot 1 faces +y: robot 0, at -x, is on its left
  EXPECT_TRUE(w.percepts[2].rab.empty());     // beyond 3 m
  EXPECT_TRUE(w.percepts[3].rab.empty());     // behind the box
  EXPECT_TRUE(w.percepts[0].rab.empty());     // not to itself
  // robot 0 stops sending at tick 1: nothing at tick 2
  control_all(p, w);
  act_all(w);
  integrate(s, w, m);
  sense_all(s, p, w);
  EXPECT_TRUE(w.percepts[1].rab.empty());
}

}  // namespace
}  // namespace swarmpath::sim
