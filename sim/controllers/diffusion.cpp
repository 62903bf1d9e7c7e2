// SPDX-License-Identifier: MIT
#include "diffusion.hpp"

#include "sim/motion.hpp"

namespace swarmpath::sim {

Command diffusion_step(const Percept& in, const Params& p, RobotMemory& mem) {
  // persistent heading with occasional random turns, then avoidance on top
  update_walk_heading(mem.walk_heading, mem.walk_dir, mem.rng, p);
  const Avoidance avoid = diffusion(in.proximity, p);
  const Vec2 walk = in.pose.to_local(mem.walk_dir);
  const Vec2 v = p.v_max * (avoid.direction + p.w_rw * walk);
  mem.state = avoid.collision ? 1 : 0;
  return drive_command(v, p, mem.turn, Led::kGreen);
}

}  // namespace swarmpath::sim
