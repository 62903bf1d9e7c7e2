// SPDX-License-Identifier: MIT
// The foundation's controller: a random walk with proximity obstacle avoidance, after the
// ARGoS diffusion/foraging examples. V = v_max (D + w_rw u_phi) (SPEC §2.1), LED green.
#pragma once

#include "sim/controller.hpp"

namespace swarmpath::sim {

Command diffusion_step(const Percept& in, const Params& p, RobotMemory& mem);

}  // namespace swarmpath::sim
