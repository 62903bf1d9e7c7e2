// SPDX-License-Identifier: MIT
// The path-formation controller (paper, "Subgoal Formation" and "Path formation strategies";
// SPEC §2.3): explorers find the goal or a RED subgoal, back off toward the nest and stop as the
// next subgoal 70 cm away, until a subgoal sees the nest; then optimisation 1 straightens the
// chain nest -> goal and optimisation 2 goal -> nest.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "sim/led.hpp"
#include "sim/params.hpp"
#include "sim/percept.hpp"

namespace swarmpath::sim {

struct RobotMemory;

/// SPEC §2.3 states (paper Table 1), with their LEDs (SPEC §2.2).
enum class PfState : std::uint8_t {
  kExploring,       ///< GREEN: random exploration away from the nest
  kReturnToNest,    ///< GRAY50: exploration budget spent, back to the nest
  kResting,         ///< BLACK: resting in the nest for T_rest
  kSubgoalForming,  ///< WHITE [P]: found the goal/a subgoal, backing off toward the nest
  kSubgoal,         ///< RED [P]: a static subgoal
  kOpt1,            ///< MAGENTA: optimisation 1, aligning between parent and child
  kSubNest,         ///< BLUE [P]: optimisation 1 done ("sub-nest")
  kOpt2,            ///< PURPLE: optimisation 2, aligning again goal -> nest
  kPathDone,        ///< BROWN: optimisation 2 done
  kRecovery,        ///< ORANGE: lost its reference; static, repels robots within r_rec
};

inline constexpr int kPfStateCount = 10;

std::string_view to_string(PfState s);
Led led_of(PfState s);

/// Something the robot keeps track of: the goal or nest beacon, or another robot.
struct Tracked {
  int id = kNobody;         ///< emitter id: a robot, kNestEmitter or kGoalEmitter
  Vec2 last_seen;           ///< global position where it was last seen [m]
  int unseen = 0;           ///< consecutive ticks it has not been seen (T_lost debounce)
  bool visible = false;     ///< seen this tick
  Led color = Led::kBlack;  ///< its colour when last seen

  bool valid() const { return id != kNobody; }
};

/// chain_bypass [R]: the robots that have named a subgoal as their parent or target.
struct Claimants {
  static constexpr int kMax = 4;
  std::array<int, kMax> ids{kNobody, kNobody, kNobody, kNobody};
  int count = 0;  ///< how many (more than kMax: the subgoal never counts itself skipped)

  void add(int robot) {
    for (int i = 0; i < std::min(count, kMax); ++i) {
      if (ids[i] == robot) return;
    }
    if (count < kMax) ids[count] = robot;
    ++count;
  }
};

/// The path-formation memory of one robot.
/// Longest chain of followers behind a guiding founder; beyond it a light is no guide.
inline constexpr int kMaxGuideHops = 30;

struct PfMemory {
  PfState state = PfState::kExploring;
  bool scout = false;          ///< task allocation's scout: explores, but row 1 is the TA's (founder)
  bool single_child = false;   ///< TA, allocated with single_child: claims and respects claims [R]
  bool backoff_spot = false;   ///< TA, allocated with ta_backoff_spot: forms at the spot toward the nest [R]
  bool seek_tip = false;       ///< TA, allocated with seek_tip: waits by a forming robot [R]
  bool bypass = false;         ///< TA, allocated with chain_bypass: skips a redundant parent [R]
  double nest_crowd_cm = 0;    ///< TA, allocated: no edge following this close to the nest [R]
  bool call_links = false;     ///< TA, allocated with recruit_call: a subgoal long unclaimed calls [R]
  std::int64_t unclaimed = 0;  ///< SUBGOAL: consecutive ticks no robot claimed it (recruit_call)
  int answering = -1;  ///< recruit_call: the calling subgoal this robot goes to (claimed on the medium)
  std::int64_t help_until = 0;  ///< refound_starved: its child went to fetch robots; it stays until this tick
  std::int64_t t_state = 0;     ///< ticks in the current state
  double t_explore = 1000;      ///< T_explore, the exploration budget [ticks]
  std::int64_t nest_ticks = 0;  ///< consecutive ticks within R_nest_reach while returning (row 3)
  bool explore_blocked = false;  ///< edge following found no way farther from the nest (row 2)
  Tracked target;                ///< what the robot backs off from while forming
  bool target_reached = true;    ///< forming: has been within d_detect of the target (row 5 needs it)
  bool far_side = false;         ///< forming: found the goal from its far side (farther from the nest)
  Vec2 last_saw_target;          ///< forming: the robot's position when it last saw the target [m]
  bool to_view_edge = false;     ///< forming: target lost, going back to last_saw_target (row 7a)
  Tracked parent;                ///< goal-side reference (the goal beacon or a robot)
  Tracked child;                 ///< nest-side reference (the nest beacon or a robot)
  Vec2 safe_pos;                 ///< aligning: where the alignment began, both references in view [m]
  bool view_limited = false;     ///< aligning: a reference went out of view; back to safe_pos
  bool seek_ref = false;         ///< aligning: looking for a reference still out of view at safe_pos
  Vec2 sighting;                 ///< where the goal or a RED subgoal was last seen [m]
  bool has_sighting = false;
  bool sighted_this_trip = false;
  bool to_sighting = false;        ///< exploring: first travelling back to the sighting (site fidelity)
  std::int64_t travel_ticks = 0;   ///< exploring: ticks spent travelling to the sighting (not budget)
  std::int64_t trip_start = 0;     ///< the tick this exploration trip began (TA t_source = elapsed)
  Claimants claimants;             ///< bypass: who has named this subgoal as parent
  bool guide = false;              ///< TA founder leading the allocated robots to the goal (LED CYAN) [R]
  bool follow_guide = false;       ///< allocated robot following the CYAN guides on its first trip [R]
  std::int64_t guide_unseen = 0;   ///< consecutive ticks a follower has seen no guide
  int guide_hops = kMaxGuideHops;  ///< follower: hops to the founder, advertised with the light
  std::uint8_t last_row = 0;       ///< the table row that fired last (index + 1; 0 = none)
  std::int64_t fired_tick = -1;    ///< the tick it fired
};

/// What the robot makes of this tick's camera blobs (computed once, before the guards).
struct PfSight {
  const Blob* goal = nullptr;      ///< the goal beacon, when visible
  const Blob* nest = nullptr;      ///< the nest beacon, when visible
  const Blob* red_near = nullptr;  ///< the nearest RED robot within d_detect
  const Blob* lure = nullptr;      ///< the goal, or else the nearest RED robot, within R_vis
  const Blob* red_nearer_nest =
      nullptr;  ///< forming: the RED robot in view nearest the nest, if nearer than the target
  const Blob* my_subnest = nullptr;    ///< the nearest BLUE robot advertising me as its parent
  const Blob* guide = nullptr;         ///< follower: the CYAN robot in view fewest hops from the founder
  const Blob* forming_link = nullptr;  ///< seek_tip: the WHITE (forming) robot in view nearest the nest
  const Blob* grandparent = nullptr;   ///< bypass: the parent's parent (RED or the goal) within d_sub + 10 cm
  const Blob* heir = nullptr;          ///< relink_recovery: the parent is ORANGE; its own parent, in view
  bool bypassed = false;               ///< bypass: every robot that named me now names another, one my parent
  bool recovery_near = false;          ///< an ORANGE robot within r_rec
  bool forming_in_view = false;        ///< a WHITE (subgoal-forming) robot within R_vis
  bool goal_claimed = false;    ///< single_child: a robot in view forms from the goal or has it as parent
  bool may_form = true;         ///< this tick's draw of p_form (one at a time)
  Vec2 repulsion;               ///< R (SPEC §2.1), robot frame
  double nest_distance_cm = 0;  ///< from the positioning sensor
};

/// Everything a guard or an action may read.
struct PfContext {
  const Percept& in;
  const Params& p;
  const PfMemory& m;
  const PfSight& sight;
  Vec2 nest;              ///< the nest's global position [m]
  bool on_trail = false;  ///< heading home along its own breadcrumbs
};

using PfGuard = bool (*)(const PfContext&);
using PfAction = void (*)(const PfContext&, PfMemory&);

/// One row of SPEC §2.3's transition table.
struct PfTransition {
  PfState from;
  PfGuard when;
  PfState to;
  PfAction act;            ///< what the transition does besides changing state (may be null)
  std::string_view row;    ///< SPEC §2.3 row, e.g. "#9a"
  std::string_view label;  ///< the paper's Table 2 label, where one exists
};

/// The table, in SPEC §2.3's order; the first row of the current state whose guard holds fires.
std::span<const PfTransition> pf_transitions();

/// Index + 1 of the table row called `row` (e.g. "#9a"), as PfMemory::last_row stores it; 0: none.
std::uint8_t pf_row_number(std::string_view row);

/// Reads the camera into `sight` and updates the tracked references (debounce, last positions).
void pf_perceive(const Percept& in, const Params& p, Vec2 nest, PfMemory& m, PfSight& sight);

/// Applies the first matching row (if any); returns it or nullptr.
const PfTransition* pf_transition(const PfContext& c, PfMemory& m);

/// One control step: perceive, transition via the table, then the state's behaviour.
Command path_formation_step(const Percept& in, const Params& p, RobotMemory& mem);

/// single_child [R]: the RED subgoal in view, nearest first, that no robot in view or on the
/// medium names as its target or parent: the end of a chain, where the next link goes.
const Blob* free_subgoal_in_view(const Percept& in);

/// rest_recruit [R]: the robot starts SUBGOAL_FORMING from `red`, a free subgoal in view; it
/// walks to it first unless within d_detect of it or nearer the nest than it (then rows 5-8).
void pf_join_chain_end(PfMemory& m, const Params& p, const Blob& red, const Pose& pose, Vec2 nest,
                       std::int64_t tick);

/// Sets up the memory of a robot starting to explore (T_explore = T_explore0).
void pf_init(PfMemory& m, const Params& p);

}  // namespace swarmpath::sim
