// SPDX-License-Identifier: MIT
// What a robot running path formation (SPEC §2.3) remembers: its state and the named sub-state of
// the states that move in legs (exploring, forming, aligning), the references it tracks and the
// places it has seen. Params are never copied here: a controller reads them from Params.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>

#include "sim/led.hpp"
#include "sim/params.hpp"
#include "sim/percept.hpp"

namespace swarmpath::sim {

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

/// Who runs path formation: every robot (without task allocation), a task-allocation scout (which
/// explores, but whose row #1 is the founder's T2), or a robot allocated by task allocation (T5,
/// T9, T10, T11), for which the task-allocation options apply (single_child, ta_backoff_spot, ...).
enum class PfRole : std::uint8_t { kSwarm, kScout, kAllocated };

/// A switch split by mode [R]: `pf` for path formation's robots, `ta` for task allocation's (its
/// scouts, allocated robots and late arrivals).
constexpr bool by_mode(PfRole role, bool pf, bool ta) { return role == PfRole::kSwarm ? pf : ta; }

/// EXPLORING's legs: a trip may first travel (following the founder out, or to the last sighting)
/// before it explores; row #2 ends it.
enum class ExploreLeg : std::uint8_t {
  kWalk,                ///< SPEC §2.1: away from the nest on a random heading (or round an obstacle)
  kToSighting,          ///< site_fidelity: travelling to the last sighting first (not budget)
  kLead,                ///< guided_departure: the founder leading the allocated robots to its sighting (CYAN)
  kFollowThenWalk,      ///< guided_departure: following the CYAN guides (not budget), then exploring
  kFollowThenSighting,  ///< guided_departure: following the CYAN guides, then to the sighting
  kTripOver,            ///< sighting_returns: row #2 ends the trip
  kToFrontier,          ///< resume_search: along the last fruitless trip's way to where it ended (not budget)
};

/// SUBGOAL_FORMING's legs.
enum class FormLeg : std::uint8_t {
  kToTarget,  ///< retarget_nearer, rest_recruit: walking to the target first (the chain's tip)
  kBackOff,   ///< back off toward the nest from the target (its trail, or the spot)
};

/// OPT1's and OPT2's legs (SPEC §2.4).
enum class AlignLeg : std::uint8_t {
  kToFoot,         ///< to the foot of the perpendicular between the references
  kBackToStart,    ///< align_keep_view: a reference slipped out of view; back to where it began
  kSeekReference,  ///< seek_hidden_reference: still out of view there; to where it was last seen
};

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

/// Longest chain of followers behind a guiding founder; beyond it a light is no guide.
inline constexpr int kMaxGuideHops = 30;

/// share_way [R]: the corners of another robot's way to the sighting it told, as they are heard.
struct ToldWay {
  static constexpr int kMax = 16;  ///< corners a way is told in
  int teller = kNobody;            ///< the robot whose sighting was taken (kNobody: none)
  int count = 0;                   ///< corners it tells (0: none heard yet)
  std::uint32_t heard = 0;         ///< bit i: corner i heard
  std::array<Vec2, kMax> corners{};

  bool complete() const { return count > 0 && heard == (std::uint32_t{1} << count) - 1U; }
};

/// The path-formation memory of one robot.
struct PfMemory {
  PfState state = PfState::kExploring;
  PfRole role = PfRole::kSwarm;
  std::int64_t t_state = 0;      ///< ticks in the current state
  double t_explore = 1000;       ///< T_explore, the exploration budget [ticks]
  std::uint8_t last_row = 0;     ///< the table row that fired last (index + 1; 0 = none)
  std::int64_t fired_tick = -1;  ///< the tick it fired
  // exploring, returning (rows #1-#4)
  ExploreLeg explore_leg = ExploreLeg::kWalk;
  std::int64_t nest_ticks = 0;     ///< consecutive ticks within R_nest_reach while returning (row 3)
  Vec2 sighting;                   ///< where the goal or a RED subgoal was last seen [m]
  bool has_sighting = false;       ///< a sighting is known (site fidelity)
  bool sighted_this_trip = false;  ///< this trip saw the goal or a RED subgoal
  std::int64_t travel_ticks = 0;   ///< ticks spent travelling (to the sighting, following): not budget
  std::int64_t trip_start = 0;     ///< the tick this exploration trip began (TA t_source = elapsed)
  int fruitless_trips = 0;         ///< trips that ended back home without a sighting (share_after_trips)
  bool resume = false;     ///< resume_search: the route holds the way of its last trip, which saw nothing
  Vec2 frontier;           ///< resume_search: where that trip ended [m]
  double w_away = 0.5;     ///< away_decay: w_away times away_decay per fruitless trip
  bool knows_way = false;  ///< share_way: its route is a way to the sighting (its own, or heard whole)
  int tell_count = -1;     ///< share_way: corners of that way in tell_corners (-1: not worked out)
  Vec2 tell_for;           ///< share_way: the sighting they were worked out for [m]
  std::array<Vec2, ToldWay::kMax> tell_corners{};  ///< share_way: the way it tells, corner by corner
  ToldWay told;                    ///< share_way: the way heard from the robot that told the sighting
  std::int64_t guide_unseen = 0;   ///< guided_departure: consecutive ticks a follower has seen no guide
  int guide_hops = kMaxGuideHops;  ///< guided_departure: hops to the founder, advertised with the light
  int answering = -1;  ///< recruit_call: the calling subgoal this robot goes to (claimed on the medium)
  // forming (rows #5-#8)
  FormLeg form_leg = FormLeg::kBackOff;
  Tracked target;              ///< what the robot backs off from while forming
  bool far_side = false;       ///< found the goal from its far side (farther from the nest than it)
  int form_retries = 0;        ///< form_retries: how often it has lost its target and gone home (row #7h)
  int way_spot_for = kNobody;  ///< spot_on_way: the target whose spot `way_spot` is (none: not chosen)
  bool has_way_spot = false;   ///< spot_on_way: its way from the nest came within the spot's distance
  Vec2 way_spot;               ///< spot_on_way: where it did [m]
  // in the chain (rows #9-#17)
  Tracked parent;  ///< goal-side reference (the goal beacon or a robot)
  Tracked child;   ///< nest-side reference (the nest beacon or a robot)
  AlignLeg align_leg = AlignLeg::kToFoot;
  Vec2 safe_pos;                ///< aligning: where the alignment began, both references in view [m]
  std::int64_t unclaimed = 0;   ///< SUBGOAL: consecutive ticks no robot claimed it (recruit_call)
  std::int64_t childless = 0;   ///< T_leaf: consecutive ticks as a SUBGOAL that no robot in view names
  std::int64_t help_until = 0;  ///< refound_starved: its child went to fetch robots; it stays until this tick
  Claimants claimants;          ///< chain_bypass: who has named this subgoal as parent
  int grandparent = kNobody;    ///< chain_repair: whom the parent's light last named as its own parent
  std::int64_t parent_gone = 0;  ///< chain_repair: consecutive ticks the parent's link light is gone
  std::int64_t child_gone = 0;   ///< chain_repair: consecutive ticks the child's link light is gone
};

/// single_child [R]: an allocated robot claims the goal or subgoal it forms from and respects others'.
inline bool claims_links(const Params& p, const PfMemory& m) {
  return m.role == PfRole::kAllocated && p.single_child;
}

/// recruit_call [R]: an allocated robot's subgoal, unclaimed for T_starve, calls resting robots.
inline bool calls_links(const Params& p, const PfMemory& m) {
  return claims_links(p, m) && p.rest_recruit && p.recruit_call;
}

/// nest_crowd [R]: how close to the nest an allocated robot does not edge-follow [cm] (0: everywhere).
inline double crowd_radius_cm(const Params& p, const PfMemory& m) {
  return m.role == PfRole::kAllocated ? p.nest_crowd : 0.0;
}

}  // namespace swarmpath::sim
