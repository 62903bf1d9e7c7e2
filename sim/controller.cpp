// SPDX-License-Identifier: MIT
#include "controller.hpp"

#include "controllers/diffusion.hpp"

namespace swarmpath::sim {

std::string_view to_string(Mode m) {
  switch (m) {
    case Mode::kDiffusion:
      return "diffusion";
  }
  return "?";
}

std::optional<Mode> parse_mode(std::string_view s) {
  if (s == "diffusion") return Mode::kDiffusion;
  return std::nullopt;
}

SensorNeeds sensor_needs(Mode m) {
  switch (m) {
    case Mode::kDiffusion:
      return {.proximity = true, .camera = false, .rab = false};
  }
  return {};
}

Led initial_led(Mode m) {
  switch (m) {
    case Mode::kDiffusion:
      return Led::kGreen;
  }
  return Led::kBlack;
}

RobotMemory init_memory(Mode m, int id, const Pose& start, const Params& p, std::uint64_t seed) {
  RobotMemory mem;
  mem.rng = Rng(mix_seed(seed, 0x726f626f74ULL /* "robot" */, static_cast<std::uint64_t>(id)));
  mem.walk_heading = start.yaw();
  mem.walk_dir = {start.c, start.s};
  mem.start = start.p;
  switch (m) {
    case Mode::kDiffusion:
      (void)p;  // the diffusion walk keeps no parameter-dependent memory
      break;
  }
  return mem;
}

Command control(Mode m, const Percept& in, const Params& p, RobotMemory& mem) {
  switch (m) {
    case Mode::kDiffusion:
      return diffusion_step(in, p, mem);
  }
  return {};
}

}  // namespace swarmpath::sim
