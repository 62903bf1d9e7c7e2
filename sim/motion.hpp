// SPDX-License-Identifier: MIT
// Shared motion primitives of SPEC §2.1: obstacle avoidance ("diffusion"), potential fields
// toward/away from a point, and the persistent random-walk heading.
#pragma once

#include <array>

#include "drive.hpp"
#include "params.hpp"
#include "percept.hpp"
#include "rng.hpp"

namespace swarmpath::sim {

struct Avoidance {
  Vec2 direction{1.0, 0.0};  ///< D, robot frame, unit length
  bool collision = false;
};

/// S = sum_i r_i (cos phi_i, sin phi_i) over the 24 proximity sensors (SPEC §2.1), robot frame.
Vec2 proximity_vector(const std::array<double, kProximityCount>& proximity);

/// S as above; clear (D = (1, 0)) when the angle of S lies within
/// +-diff_angle and |S| < diff_delta, otherwise D = -S/|S| and collision = true.
Avoidance diffusion(const std::array<double, kProximityCount>& proximity, const Params& p);

/// The command that drives along `v_cm_s` (robot frame, cm/s) by the wheel mapping of SPEC §1.2
/// (`turn` keeps its hysteresis), showing `led`.
Command drive_command(Vec2 v_cm_s, const Params& p, TurnMode& turn, Led led);

/// Robot-frame unit vector toward `target` (Eq. 4-5 with atan2): F_toward; -F is F_away.
/// Zero when the robot is on the target.
Vec2 field_toward(const Pose& pose, Vec2 target);

/// Random-walk heading phi (global frame): with probability p_turn add U(-dphi_max, +dphi_max);
/// `dir` follows as unit(phi).
void update_walk_heading(double& heading, Vec2& dir, Rng& rng, const Params& p);

}  // namespace swarmpath::sim
