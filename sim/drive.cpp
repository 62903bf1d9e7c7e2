// SPDX-License-Identifier: MIT
#include "drive.hpp"

#include <algorithm>
#include <cmath>

namespace swarmpath::sim {

WheelSpeeds wheels_from_vector(Vec2 v, const Params& p, TurnMode& mode) {
  const double b = std::min(norm(v), p.v_max);
  const double hard = deg2rad(p.theta_hard);
  const double soft = deg2rad(p.theta_soft);
  const double none = deg2rad(p.theta_none);
  // Surely inside the no-turn cone, |a| <= none (atan t <= t, with a margin far above atan2's
  // rounding): from any mode the cascade below ends in NONE with both wheels at b, so the angle
  // (an atan2, the most of this function) is not needed.
  if (none <= soft && none <= hard && v.x > 0.0 && std::fabs(v.y) <= (1.0 - 1e-9) * none * v.x) {
    mode = TurnMode::kNone;
    return {b, b};
  }
  const double a = angle_of(v);  // (-pi, pi]; 0 for a zero vector
  const double abs_a = std::fabs(a);

  // hysteresis: a cascade, so HARD can fall through to SOFT and then NONE in one call
  if (mode == TurnMode::kHard && abs_a <= soft) mode = TurnMode::kSoft;
  if (mode == TurnMode::kSoft) {
    if (abs_a > hard) {
      mode = TurnMode::kHard;
    } else if (abs_a <= none) {
      mode = TurnMode::kNone;
    }
  }
  if (mode == TurnMode::kNone) {
    if (abs_a > hard) {
      mode = TurnMode::kHard;
    } else if (abs_a > none) {
      mode = TurnMode::kSoft;
    }
  }

  double inner = 0;
  double outer = 0;
  switch (mode) {
    case TurnMode::kNone:
      inner = outer = b;
      break;
    case TurnMode::kSoft: {
      const double f = (hard - abs_a) / hard;
      inner = b * f;
      outer = b * (2.0 - f);
      break;
    }
    case TurnMode::kHard:
      inner = -p.v_max;
      outer = p.v_max;
      break;
  }
  // a > 0: turn left, the left wheel is the inner one
  return a > 0.0 ? WheelSpeeds{inner, outer} : WheelSpeeds{outer, inner};
}

}  // namespace swarmpath::sim
