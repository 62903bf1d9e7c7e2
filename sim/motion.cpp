// SPDX-License-Identifier: MIT
#include "motion.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

namespace swarmpath::sim {

Vec2 proximity_vector(const std::array<double, kProximityCount>& proximity) {
  const auto& dirs = proximity_directions();
  Vec2 s;
  for (std::size_t k = 0; k < kProximityCount; ++k) s += proximity[k] * dirs[k];
  return s;
}

Avoidance diffusion(const std::array<double, kProximityCount>& proximity, const Params& p) {
  // nothing in range, the usual case (every reading +0 or -0, their bits but the sign 0): the sum
  // below would be (+0, +0), so its length 0
  std::uint64_t bits = 0;
  for (const double r : proximity) bits |= std::bit_cast<std::uint64_t>(r);
  if ((bits << 1) == 0) return {};
  const Vec2 s = proximity_vector(proximity);
  const double len = norm(s);
  if (len == 0.0) return {};  // nothing in range: straight ahead (angle 0, length 0)
  if (len < p.diff_delta && std::fabs(angle_of(s)) <= deg2rad(p.diff_angle)) return {};
  return {(-1.0 / len) * s, true};
}

Command drive_command(Vec2 v_cm_s, const Params& p, TurnMode& turn, Led led) {
  const WheelSpeeds w = wheels_from_vector(v_cm_s, p, turn);
  Command cmd;
  cmd.left_cm_s = w.left_cm_s;
  cmd.right_cm_s = w.right_cm_s;
  cmd.led = led;
  return cmd;
}

Vec2 field_toward(const Pose& pose, Vec2 target) {
  const Vec2 d = target - pose.p;
  const double len = norm(d);
  if (len == 0.0) return {};
  return pose.to_local((1.0 / len) * d);
}

void update_walk_heading(double& heading, Vec2& dir, Rng& rng, const Params& p) {
  if (rng.bernoulli(p.p_turn)) {
    heading = wrap_angle(heading + deg2rad(p.dphi_max) * rng.uniform(-1.0, 1.0));
    dir = unit(heading);
  }
}

}  // namespace swarmpath::sim
