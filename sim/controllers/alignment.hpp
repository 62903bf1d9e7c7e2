// SPDX-License-Identifier: MIT
// The two optimisation passes (SPEC §2.4; paper, "Path formation strategies": theta1, theta2, x, y
// and the error angle): the geometry, pure functions in the robot frame (the robot is the origin);
// rows #10-#13 and the aligning robot's behaviour, in its legs (AlignLeg).
#pragma once

#include "pf_perception.hpp"
#include "sim/params.hpp"
#include "sim/percept.hpp"
#include "sim/vec2.hpp"

namespace swarmpath::sim {

struct RobotMemory;

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

// guards
bool alignment_done(const PfContext& c);               ///< #10, #12 (label a)
bool parent_done_or_last_subgoal(const PfContext& c);  ///< #11, label h
bool reference_lost(const PfContext& c);               ///< #13, label f

/// OPT1 / OPT2 (LED magenta / purple): to the foot of the perpendicular (SPEC §2.4), in the legs of
/// AlignLeg.
Command align(const Percept& in, const Params& p, RobotMemory& mem, PfState s);

/// Drives at the alignment speed toward where a reference out of view was last seen (robot frame, cm).
Command look_for(const Percept& in, const Params& p, RobotMemory& mem, Vec2 toward, PfState s);

}  // namespace swarmpath::sim
