// SPDX-License-Identifier: MIT
// The task-allocation controller (paper, "Task allocation model" and "Local Communication
// Protocol"; SPEC §2.6-2.7): scouts explore; the scout that finds the goal becomes the goal
// founder, computes n = l/v + delta from its exploring time, returns to the nest and allocates n
// robots over the range-and-bearing medium; the allocated robots run path formation, the others
// go back to their deployment points and rest.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "sim/led.hpp"
#include "sim/params.hpp"
#include "sim/percept.hpp"
#include "ta_protocol.hpp"

namespace swarmpath::sim {

struct RobotMemory;

/// SPEC §2.6's states (paper Table 3). A scout's own exploring, returning and resting run on the
/// path-formation controller (its states and budget); INITIATE_TASK hands the robot to it.
enum class TaState : std::uint8_t {
  kScout,          ///< exploring / returning / resting, as path formation's rows #2-#4 (TA a, b)
  kGoalFounder,    ///< CYAN: found the goal, back to the nest, runs the protocol (TA c, PF j/k)
  kDecisionMaker,  ///< GRAY80: at the nest, answering the founder (TA f)
  kPathFormation,  ///< allocated (INITIATE_TASK, TA e): the path-formation controller
  kRestingTask,    ///< not allocated: back to its deployment point, LEDs off (TA d)
};

inline constexpr int kTaStateCount = 5;

std::string_view to_string(TaState s);

struct TaMemory {
  TaState state = TaState::kScout;
  std::int64_t t_state = 0;
  // goal founder
  double t_founder_s = 0;  ///< t of Eq. (1) [s]
  int n = 0;               ///< robots needed, Eq. (3) (the founder included when it counts itself)
  bool protocol_started = false;
  FounderProtocol protocol;
  std::int64_t alloc_done_tick = -1;  ///< the tick it first broadcast DONE (T_alloc)
  int allocated = -1;                 ///< then: robots allocated, itself included when it counts itself
  double nest_best_cm = 1e18;         ///< founder_in_crowd [R]: its least distance to the nest so far [cm]
  std::int64_t held = 0;              ///< ... ticks since that improved by trap_progress
  // decision maker
  std::int64_t waited = 0;       ///< ticks at the nest without hearing a REQUEST
  bool request_ever = false;     ///< dm_rescout [R]: it has heard a REQUEST as a decision maker
  bool rescouted = false;        ///< dm_rescout: a scout again; GRAY80 lights alone no longer call it
  std::int64_t depart_tick = 0;  ///< allocated: the tick it leaves the nest (depart_gap) [R]
  // resting task
  bool arrived = false;
  bool settled = false;       ///< at its deployment point, touch_base taken [R]
  double touch_base = 0;      ///< the proximity vector's length when it settled (static neighbours) [R]
  std::int64_t give_way = 0;  ///< ticks left backing away from a robot pressing on it (give_way) [R]
  Vec2 give_dir;              ///< the way it backs away, robot frame
  std::int64_t end_seen = 0;  ///< rest_recruit [R]: consecutive ticks a chain's end has been in view
  std::int64_t end_wait = 0;  ///< rest_recruit: ticks it waits before joining (T_recruit + a draw)
  // refound_starved [R]: a chain's end gone home to allocate the rest of the path's robots
  bool refounder = false;
  int left_parent = kNobody;  ///< the subgoal it left (told with fetch messages on its way)
  std::uint8_t last_row = 0;  ///< the TA table row that fired last (index + 1)
  std::int64_t fired_tick = -1;
};

/// What the robot hears and sees that the TA rows need.
struct TaSight {
  bool goal_found = false;          ///< goal beacon within d_detect
  bool exploring = true;            ///< a scout on its way out (not going home or resting)
  bool founder_or_dm_seen = false;  ///< a CYAN or GRAY80 robot within R_vis
  bool founder_seen = false;        ///< ... a CYAN one (a founder)
  bool path_colour_seen = false;    ///< a robot in a path-formation state (SPEC T7)
  bool request_heard = false;
  bool alloc_done_heard = false;
  std::uint8_t senior_founder = kBroadcastId;  ///< a founder that outranks this one (T8)
  DmTick dm;                                   ///< the decision maker's reading of the inbox
  const Blob* chain_end = nullptr;   ///< rest_recruit, resting at its deployment point: a free RED subgoal
  const RabMessage* call = nullptr;  ///< recruit_call: the nearest subgoal calling for a link, unanswered
  bool left_alone = false;           ///< refound_starved: a chain's end unclaimed for T_refound
  double nest_distance_cm = 0;
};

struct TaContext {
  const Percept& in;
  const Params& p;
  const TaMemory& m;
  const TaSight& sight;
  int swarm;  ///< N, for the clamp of n
};

using TaGuard = bool (*)(const TaContext&);
using TaAction = void (*)(const TaContext&, RobotMemory&);

struct TaTransition {
  TaState from;
  TaGuard when;
  TaState to;
  TaAction act;
  std::string_view row;    ///< SPEC §2.6 row (T2 ... T9)
  std::string_view label;  ///< the paper's TA Table labels (a-f) or path-formation labels (j, k)
};

std::span<const TaTransition> ta_transitions();

/// Index + 1 of the table row called `row` (e.g. "T10"), as TaMemory::last_row stores it; 0: none.
std::uint8_t ta_row_number(std::string_view row);

/// Reads the camera and the RAB inbox, and the robot's own state (its nest, its trip, whether it
/// has ACKed robots), into `sight`.
void ta_perceive(const Percept& in, const Params& p, const RobotMemory& mem, TaSight& sight);

/// Applies the first matching row (if any); returns it or nullptr.
const TaTransition* ta_transition(const TaContext& c, RobotMemory& mem);

/// The kinds of message (kKind*) a robot reads in its current state: those its perception reads, and
/// those the state a row takes it to this tick reads (a founder's JOINs, path formation's claims).
/// Whether it listens at all is robot_listens's (sim/controller.hpp).
RabKinds ta_interest(const Params& p, const RobotMemory& mem);

/// One control step of a robot in task-allocation mode (N = `swarm` robots).
Command task_allocation_step(const Percept& in, const Params& p, RobotMemory& mem, int swarm);

/// Sets up a scout.
void ta_init(RobotMemory& mem, const Params& p);

/// The delta of Eq. (3) for an environment class (SPEC §2.7, rows 33-35).
double delta_for(const Params& p, std::uint8_t env_class);

}  // namespace swarmpath::sim
