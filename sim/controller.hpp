// SPDX-License-Identifier: MIT
// The controllers a world can run, their per-robot memory and the dispatch the step uses.
// Controllers see a Percept and return a Command; they never see Box2D or the World.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "controllers/navigation.hpp"
#include "controllers/path_formation.hpp"
#include "controllers/route.hpp"
#include "controllers/task_allocation.hpp"
#include "drive.hpp"
#include "motion.hpp"
#include "params.hpp"
#include "percept.hpp"
#include "rng.hpp"

namespace swarmpath::sim {

/// Which controller every robot runs.
enum class Mode : std::uint8_t {
  kDiffusion,       ///< random walk with proximity obstacle avoidance (ARGoS diffusion example)
  kPathFormation,   ///< the paper's path formation, all robots (SPEC §2.3, "without TA")
  kTaskAllocation,  ///< task allocation, then path formation by the allocated robots (SPEC §2.6, "with TA")
};

/// Every mode, for listings and --help.
inline constexpr Mode kModes[] = {Mode::kDiffusion, Mode::kPathFormation, Mode::kTaskAllocation};

std::string_view to_string(Mode m);
std::optional<Mode> parse_mode(std::string_view s);

/// Per-robot controller memory: everything a controller keeps between ticks.
struct RobotMemory {
  Rng rng;                          ///< this robot's own stream: splitmix64(seed ^ id)
  TurnMode turn = TurnMode::kNone;  ///< wheel-mapping hysteresis (SPEC §1.2)
  double walk_heading = 0;          ///< random-walk heading phi, global frame [rad]
  Vec2 walk_dir{1.0, 0.0};          ///< unit(walk_heading), refreshed when phi changes
  std::uint8_t state = 0;           ///< the controller's state code (part of state_hash)
  Vec2 start;                       ///< initial deployment point [m]
  Vec2 nest;                        ///< the nest's position, from the positioning frame [m]
  PfMemory pf;                      ///< path formation (also a TA scout's and allocated robot's)
  TaMemory ta;                      ///< task allocation (Mode::kTaskAllocation)
  std::uint8_t env_class = 0;       ///< the scenario's EnvClass (selects delta, Eq. 3)
  int swarm = 0;                    ///< N, the robots deployed
  NavMemory nav;                    ///< going to a point (nest, deployment point)
  Trail trail;                      ///< breadcrumbs of the current exploration trip
  Route route;                      ///< route_to_sighting: the crumbs of the trip that saw the sighting
};

/// Which sensors mode `m` reads (path formation the medium only with share_sighting).
SensorNeeds sensor_needs(Mode m, const Params& p);

/// Whether one robot listens to the range-and-bearing medium in its current state, when the world
/// senses it at all: in task allocation, only scouts, founders and decision makers do; in path
/// formation, resting robots without a sighting, at `tick`, once a telling can reach them (share_sighting).
bool robot_listens(Mode m, const Params& p, const RobotMemory& mem, std::int64_t tick);

/// The kinds of message (RabKinds bits) a payload broadcast in mode `m` carries: the medium delivers
/// it only to robots that read one of them (kEveryRabKind outside task allocation).
RabKinds rab_kinds(Mode m, const RabPayload& payload);

/// The kinds of message robot `mem` reads this tick, in its state before its control step: 0 when it
/// does not listen (robot_listens), else every kind that a reading of its inbox in this tick may look
/// at, whatever row fires (ta_interest).
RabKinds rab_interest(Mode m, const Params& p, const RobotMemory& mem, std::int64_t tick);

/// The LED colour robots show before their first control step.
Led initial_led(Mode m);

/// Sets up robot `id`'s memory at deployment.
RobotMemory init_memory(Mode m, int id, const Pose& start, Vec2 nest, const Params& p, std::uint64_t seed);

/// The name of a robot's state code (RobotMemory::state) in mode `m`, from the controllers' own
/// names: "exploring" in path formation, "path_formation/subgoal" (task allocation, then path
/// formation) in task allocation, "walk" or "avoid" in diffusion; "?" for a code no state has.
std::string state_code_name(Mode m, std::uint8_t code);

/// One control step of robot `in.id`.
Command control(Mode m, const Percept& in, const Params& p, RobotMemory& mem);

}  // namespace swarmpath::sim
