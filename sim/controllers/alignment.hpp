// SPDX-License-Identifier: MIT
// The optimisation geometry of SPEC §2.4 (paper, "Path formation strategies": theta1, theta2, x,
// y and the error angle). Pure functions in the robot frame: the robot is the origin.
#pragma once

#include "sim/params.hpp"
#include "sim/vec2.hpp"

namespace swarmpath::sim {

/// e = pi - |wrap(theta1 - theta2)|, in [0, pi]; 0 when the robot lies on the segment A-B.
/// theta1: bearing to the goal-side reference A; theta2: bearing to the nest-side reference B.
double error_angle(double theta1, double theta2);

/// The point the aligning robot drives to, robot frame [cm]: the foot of the perpendicular from
/// the robot onto A-B, t* = clamp(-A.(B-A)/|B-A|^2, 0, 1), clamped so that it stays within R_keep
/// of both references (the midpoint when no such point exists), blended toward the midpoint by
/// lambda_mid. A = x (cos theta1, sin theta1), B = y (cos theta2, sin theta2), x and y in cm.
Vec2 alignment_target(Vec2 a, Vec2 b, const Params& p);

/// The SPEC §2.4 stop test: e <= e_tol, or |P| <= d_tol.
bool aligned(double theta1, double theta2, Vec2 target, const Params& p);

}  // namespace swarmpath::sim
