// SPDX-License-Identifier: MIT
#include "controller.hpp"

#include "controllers/diffusion.hpp"
#include "controllers/founder_way.hpp"
#include "controllers/path_formation.hpp"
#include "controllers/sighting_share.hpp"

namespace swarmpath::sim {

std::string_view to_string(Mode m) {
  switch (m) {
    case Mode::kDiffusion:
      return "diffusion";
    case Mode::kPathFormation:
      return "pf";
    case Mode::kTaskAllocation:
      return "ta";
  }
  return "?";
}

std::optional<Mode> parse_mode(std::string_view s) {
  for (const Mode m : kModes) {
    if (s == to_string(m)) return m;
  }
  return std::nullopt;
}

SensorNeeds sensor_needs(Mode m, const Params& p) {
  switch (m) {
    case Mode::kDiffusion:
      return {.proximity = true, .camera = false, .rab = false};
    case Mode::kPathFormation:
      return {.proximity = true, .camera = true, .rab = p.share_sighting > 0.0};
    case Mode::kTaskAllocation:
      return {.proximity = true, .camera = true, .rab = true};
  }
  return {};
}

bool robot_listens(Mode m, const Params& p, const RobotMemory& mem, std::int64_t tick) {
  if (m == Mode::kPathFormation)  // share_sighting, share_way [R]
    return listens_for_sighting(p, mem.pf, tick) || listens_for_way(p, mem.pf);
  if (m != Mode::kTaskAllocation) return true;  // the world's needs.rab decides
  return mem.ta.state == TaState::kScout || mem.ta.state == TaState::kGoalFounder ||
         mem.ta.state == TaState::kDecisionMaker || claims_links(p, mem.pf) ||
         listens_for_founder_way(p, mem, tick) ||
         (mem.ta.state == TaState::kRestingTask && p.rest_recruit && p.recruit_call);
}

RabKinds rab_kinds(Mode m, const RabPayload& payload) {
  return m == Mode::kTaskAllocation ? message_kinds(decode(payload)) : kEveryRabKind;
}

RabKinds rab_interest(Mode m, const Params& p, const RobotMemory& mem, std::int64_t tick) {
  if (!robot_listens(m, p, mem, tick)) return 0;
  return m == Mode::kTaskAllocation ? ta_interest(p, mem) : kEveryRabKind;
}

Led initial_led(Mode m) {
  switch (m) {
    case Mode::kDiffusion:
      return Led::kGreen;
    case Mode::kPathFormation:
    case Mode::kTaskAllocation:
      return led_of(PfState::kExploring);
  }
  return Led::kBlack;
}

RobotMemory init_memory(Mode m, int id, const Pose& start, Vec2 nest, const Params& p, std::uint64_t seed) {
  RobotMemory mem;
  mem.rng = Rng(mix_seed(seed, 0x726f626f74ULL /* "robot" */, static_cast<std::uint64_t>(id)));
  mem.walk_heading = start.yaw();
  mem.walk_dir = {start.c, start.s};
  mem.start = start.p;
  mem.nest = nest;
  switch (m) {
    case Mode::kDiffusion:
      break;
    case Mode::kPathFormation:
      pf_init(mem.pf, p);
      mem.trail.reset(start.p);
      mem.state = static_cast<std::uint8_t>(mem.pf.state);
      break;
    case Mode::kTaskAllocation:
      ta_init(mem, p);
      mem.trail.reset(start.p);
      break;
  }
  return mem;
}

std::string state_code_name(Mode m, std::uint8_t code) {
  switch (m) {
    case Mode::kDiffusion:
      return code == 0 ? "walk" : code == 1 ? "avoid" : "?";
    case Mode::kPathFormation:
      return code < kPfStateCount ? std::string(to_string(static_cast<PfState>(code))) : "?";
    case Mode::kTaskAllocation: {
      // task_allocation_step's code: TaState * 16 + PfState
      const int ta = code / 16, pf = code % 16;
      if (ta >= kTaStateCount || pf >= kPfStateCount) return "?";
      return std::string(to_string(static_cast<TaState>(ta))) + "/" +
             std::string(to_string(static_cast<PfState>(pf)));
    }
  }
  return "?";
}

Command control(Mode m, const Percept& in, const Params& p, RobotMemory& mem) {
  switch (m) {
    case Mode::kDiffusion:
      return diffusion_step(in, p, mem);
    case Mode::kPathFormation:
      return path_formation_step(in, p, mem);
    case Mode::kTaskAllocation:
      return task_allocation_step(in, p, mem, mem.swarm);
  }
  return {};
}

}  // namespace swarmpath::sim
