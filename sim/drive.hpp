// SPDX-License-Identifier: MIT
// Vector-to-wheels mapping of the ARGoS foraging example (SPEC §1.2): a three-mode turning
// state machine with hysteresis (hard / soft / no turn).
#pragma once

#include <cstdint>

#include "params.hpp"
#include "vec2.hpp"

namespace swarmpath::sim {

enum class TurnMode : std::uint8_t { kNone, kSoft, kHard };

struct WheelSpeeds {
  double left_cm_s = 0;
  double right_cm_s = 0;
};

/// Wheel speeds that follow `v` (robot frame, cm/s): a = signed angle of v, b = min(|v|, v_max).
/// Updates the turning mode: HARD->SOFT when |a| <= theta_soft; SOFT->HARD when |a| > theta_hard,
/// SOFT->NONE when |a| <= theta_none; NONE->HARD when |a| > theta_hard, NONE->SOFT when
/// |a| > theta_none (checked in that cascade, as the foraging example does).
WheelSpeeds wheels_from_vector(Vec2 v, const Params& p, TurnMode& mode);

}  // namespace swarmpath::sim
