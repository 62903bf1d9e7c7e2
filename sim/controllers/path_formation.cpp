// SPDX-License-Identifier: MIT
#include "path_formation.hpp"

#include <array>

#include "alignment.hpp"
#include "chain_links.hpp"
#include "chain_repair.hpp"
#include "exploring.hpp"
#include "forming.hpp"
#include "navigation.hpp"
#include "sighting_share.hpp"
#include "sim/controller.hpp"
#include "sim/motion.hpp"
#include "transition_table.hpp"

namespace swarmpath::sim {

std::string_view to_string(PfState s) {
  switch (s) {
    case PfState::kExploring:
      return "exploring";
    case PfState::kReturnToNest:
      return "return_to_nest";
    case PfState::kResting:
      return "resting";
    case PfState::kSubgoalForming:
      return "subgoal_forming";
    case PfState::kSubgoal:
      return "subgoal";
    case PfState::kOpt1:
      return "opt1";
    case PfState::kSubNest:
      return "sub_nest";
    case PfState::kOpt2:
      return "opt2";
    case PfState::kPathDone:
      return "path_done";
    case PfState::kRecovery:
      return "recovery";
  }
  return "?";
}

Led led_of(PfState s) {
  switch (s) {
    case PfState::kExploring:
      return Led::kGreen;
    case PfState::kReturnToNest:
      return Led::kGray50;
    case PfState::kResting:
      return Led::kBlack;
    case PfState::kSubgoalForming:
      return Led::kWhite;
    case PfState::kSubgoal:
      return Led::kRed;
    case PfState::kOpt1:
      return Led::kMagenta;
    case PfState::kSubNest:
      return Led::kBlue;
    case PfState::kOpt2:
      return Led::kPurple;
    case PfState::kPathDone:
      return Led::kBrown;
    case PfState::kRecovery:
      return Led::kOrange;
  }
  return Led::kBlack;
}

void pf_init(PfMemory& m, const Params& p, PfRole role) {
  m = PfMemory{};
  m.role = role;
  m.t_explore = p.t_explore0;
  m.w_away = p.w_away;
}

Command pf_drive(const Params& p, RobotMemory& mem, Vec2 v_cm_s, PfState s) {
  return drive_command(v_cm_s, p, mem.turn, led_of(s));
}

Command pf_stop(PfState s) {
  Command cmd;
  cmd.led = led_of(s);
  return cmd;
}

namespace {

// clang-format off
// SPEC §2.3, in its order (paper Table 2 labels where they exist). For each state the first row
// whose guard holds fires; rows 6, 8, 9 and 13 are split where the SPEC lists two conditions. Rows
// with a letter or a number past 14 are [R] (docs/CHOICES.md): #1h return_finds, #5r retarget_nearer,
// #7h form_retries (rows #7 and #8b go home instead, docs/detours.md),
// #15-#16 chain_bypass, #21 T_leaf, #17 relink_recovery, #18-#20 chain_repair (before the rows that would act on
// a gone neighbour).
constexpr std::array<PfTransition, 34> kTable{{
  {PfState::kExploring,      found_goal_or_subgoal,        PfState::kSubgoalForming, take_target,           "#1",  "c"},
  {PfState::kExploring,      exploration_time_over,        PfState::kReturnToNest,   nullptr,               "#2",  "b"},
  {PfState::kReturnToNest,   found_on_the_way_home,        PfState::kSubgoalForming, take_target,           "#1h", "c"},
  {PfState::kReturnToNest,   reached_nest,                 PfState::kResting,        nullptr,               "#3",  "d"},
  {PfState::kResting,        resting_time_over,            PfState::kExploring,      grow_budget,           "#4",  "i"},
  {PfState::kSubgoalForming, found_subgoal_nearer_nest,    PfState::kSubgoalForming, retarget,              "#5r", "c"},
  {PfState::kSubgoalForming, target_at_subgoal_distance,   PfState::kSubgoal,        target_becomes_parent, "#5",  ""},
  {PfState::kSubgoalForming, reached_nest_before_d_sub,    PfState::kSubgoal,        target_becomes_parent, "#6a", ""},
  {PfState::kSubgoalForming, entered_recovery_range,       PfState::kSubgoal,        target_becomes_parent, "#6b", ""},
  {PfState::kSubgoalForming, lost_target_may_retry,        PfState::kReturnToNest,   go_home_to_retry,      "#7h", ""},
  {PfState::kSubgoalForming, target_lost_in_visible_range, PfState::kRecovery,       nullptr,               "#7",  "f"},
  {PfState::kSubgoalForming, forming_timeout_target_seen,  PfState::kSubgoal,        target_becomes_parent, "#8a", ""},
  {PfState::kSubgoalForming, forming_timeout,              PfState::kRecovery,       nullptr,               "#8b", ""},
  {PfState::kSubgoal,        parent_gone_heir_in_view,     PfState::kSubgoal,        relink_over_gap,       "#18a",""},
  {PfState::kSubgoal,        parent_gone,                  PfState::kReturnToNest,   leave_broken_chain,    "#19a",""},
  {PfState::kSubgoal,        sees_nest,                    PfState::kOpt1,           child_is_nest,         "#9a", "g"},
  {PfState::kSubgoal,        sees_own_sub_nest,            PfState::kOpt1,           child_is_sub_nest,     "#9b", "g"},
  {PfState::kOpt1,           alignment_done,               PfState::kSubNest,        nullptr,               "#10", ""},
  {PfState::kSubNest,        parent_gone_heir_in_view,     PfState::kSubNest,        relink_over_gap,       "#18b",""},
  {PfState::kSubNest,        parent_gone,                  PfState::kReturnToNest,   leave_broken_chain,    "#19b",""},
  {PfState::kSubNest,        child_gone,                   PfState::kSubgoal,        become_tip,            "#20a",""},
  {PfState::kSubNest,        parent_done_or_last_subgoal,  PfState::kOpt2,           nullptr,               "#11", "h"},
  {PfState::kOpt2,           alignment_done,               PfState::kPathDone,       nullptr,               "#12", "a"},
  {PfState::kOpt1,           reference_lost,               PfState::kRecovery,       nullptr,               "#13a","f"},
  {PfState::kOpt2,           reference_lost,               PfState::kRecovery,       nullptr,               "#13b","f"},
  {PfState::kSubNest,        orphaned,                     PfState::kSubgoal,        nullptr,               "#14a",""},
  {PfState::kPathDone,       parent_gone_heir_in_view,     PfState::kPathDone,       relink_over_gap,       "#18c",""},
  {PfState::kPathDone,       parent_gone,                  PfState::kReturnToNest,   leave_broken_chain,    "#19c",""},
  {PfState::kPathDone,       child_gone,                   PfState::kSubgoal,        become_tip,            "#20b",""},
  {PfState::kPathDone,       orphaned,                     PfState::kSubgoal,        nullptr,               "#14b",""},
  {PfState::kSubgoal,        sees_grandparent,             PfState::kSubgoal,        grandparent_becomes_parent, "#15", ""},
  {PfState::kSubgoal,        bypassed,                     PfState::kReturnToNest,   leave_chain,           "#16", ""},
  {PfState::kSubNest,        heir_in_view,                 PfState::kSubNest,        heir_becomes_parent,   "#17", ""},
  {PfState::kSubgoal,        leaf_unextended,              PfState::kReturnToNest,   leave_chain,           "#21", ""},
}};

// clang-format on

constexpr auto kRowsOf = rows_by_state<kPfStateCount>(kTable);
static_assert(kRowsOf.begin[kPfStateCount] == kTable.size(), "a row whose state is out of range");

// What every transition starts afresh: the navigator, the legs of the state it enters (forming's
// are set by the row's action), the chain's bookkeeping; a new trip (row #4) starts its trail.
void enter(const Percept& in, const Params& p, RobotMemory& mem, PfState to) {
  PfMemory& m = mem.pf;
  nav_reset(mem.nav);
  m.align_leg = AlignLeg::kToFoot;
  m.safe_pos = in.pose.p;
  m.claimants = Claimants{};
  m.answering = -1;
  m.explore_leg = ExploreLeg::kWalk;
  if (to == PfState::kReturnToNest && !m.sighted_this_trip) m.has_sighting = false;  // a stale lead
  // R (resume_search): a trip home without a sighting keeps its way, for the next trip to resume
  if (to == PfState::kReturnToNest) m.resume = p.resume_search && !m.has_sighting && keep_frontier(mem);
  if (to == PfState::kResting && !m.has_sighting) {  // home without a sighting
    ++m.fruitless_trips;
    m.w_away *= p.away_decay;  // R (away_decay): less of the away field on the next trip
  }
  // R (route_to_sighting, walk_way, share_way): the way out of a trip that saw the chain, for the next trip
  // to it and to tell; a way heard from another robot is done with once the trip it led is over
  if (to == PfState::kReturnToNest) {
    m.told = ToldWay{};
    m.knows_way = false;
    if ((p.route_to_sighting || p.walk_way || p.share_way) && m.has_sighting) {
      mem.route.keep(mem.trail);
      m.knows_way = true;
      m.tell_count = -1;
    }
  }
  if (to == PfState::kExploring) {
    // a new trip: head for the last sighting (site fidelity), else keep the random heading
    m.sighted_this_trip = false;
    mem.trail.reset(in.pose.p);
    m.explore_leg = first_leg(p, m);
    if (m.explore_leg == ExploreLeg::kWalk && m.resume) m.explore_leg = ExploreLeg::kToFrontier;
    m.travel_ticks = 0;
    m.trip_start = in.tick;
  }
}

// the state's behaviour
Command act(const Percept& in, const Params& p, RobotMemory& mem, const PfSight& sight) {
  const PfState s = mem.pf.state;
  switch (s) {
    case PfState::kExploring:
      return explore(in, p, mem, sight);
    case PfState::kReturnToNest:
      return go_to_nest(in, p, mem, sight, s);
    case PfState::kSubgoalForming:
      return form_subgoal(in, p, mem, sight);
    case PfState::kOpt1:
    case PfState::kOpt2:
      return align(in, p, mem, s);
    case PfState::kSubNest:
      return wait_for_parent(in, p, mem);
    case PfState::kResting:
    case PfState::kSubgoal:
    case PfState::kPathDone:
    case PfState::kRecovery:
      return pf_stop(s);
  }
  return pf_stop(s);
}

}  // namespace

std::span<const PfTransition> pf_transitions() { return kTable; }

std::uint8_t pf_row_number(std::string_view row) { return row_number(pf_transitions(), row); }

const PfTransition* pf_transition(const PfContext& c, PfMemory& m) {
  for (const std::size_t i : kRowsOf.of(static_cast<std::size_t>(m.state))) {
    const PfTransition& row = kTable[i];
    if (!row.when(c)) continue;
    if (row.act != nullptr) row.act(c, m);
    m.state = row.to;
    m.t_state = 0;
    m.last_row = static_cast<std::uint8_t>(i + 1);
    m.fired_tick = c.in.tick;
    return &row;
  }
  return nullptr;
}

Command path_formation_step(const Percept& in, const Params& p, RobotMemory& mem) {
  PfMemory& m = mem.pf;
  PfSight sight;
  pf_perceive(in, p, mem.nest, m, sight);
  if (listens_for_sighting(p, m, in.tick)) hear_sighting(in.rab, mem.nest, m);        // share_sighting [R]
  if (listens_for_way(p, m) && hear_way(in.rab, mem.nest, m) && m.told.complete()) {  // share_way [R]
    mem.route.assign(std::span<const Vec2>(m.told.corners.data(), static_cast<std::size_t>(m.told.count)));
    m.knows_way = true;
    m.tell_count = -1;
  }
  if (m.state == PfState::kSubgoalForming) next_form_leg(in, p, m);
  sight.may_form = !p.form_one_at_a_time || m.state != PfState::kExploring || sight.lure == nullptr ||
                   mem.rng.bernoulli(p.p_form);
  // transitions happen only here, via the table
  const PfContext c{in, p, m, sight, mem.nest, mem.nav.on_trail, mem.trail.went_round()};
  if (const PfTransition* fired = pf_transition(c, m)) enter(in, p, mem, fired->to);
  ++m.t_state;
  mem.state = static_cast<std::uint8_t>(m.state);
  Command cmd = act(in, p, mem, sight);
  advertise_links(in, p, m, cmd);
  work_out_way(p, mem.route, m);
  if (tells_sighting(p, m, sight.nest_distance_cm, in.tick) &&
      !tell_way(in.id, mem.nest, p, mem.route, m, in.tick, cmd))
    tell_sighting(in.id, mem.nest, m, cmd);
  return cmd;
}

}  // namespace swarmpath::sim
