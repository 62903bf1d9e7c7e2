// SPDX-License-Identifier: MIT
#include "task_allocation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "chain_links.hpp"
#include "colours.hpp"
#include "exploring.hpp"
#include "forming.hpp"
#include "founder_way.hpp"
#include "navigation.hpp"
#include "path_formation.hpp"
#include "resting.hpp"
#include "sim/controller.hpp"
#include "sim/motion.hpp"
#include "transition_table.hpp"
#include "units.hpp"

namespace swarmpath::sim {

// a claim (single_child) names its sender's state as the TA state it is in
static_assert(kClaimState == static_cast<std::uint8_t>(TaState::kPathFormation));
static_assert(kFounderState == static_cast<std::uint8_t>(TaState::kGoalFounder));

std::string_view to_string(TaState s) {
  switch (s) {
    case TaState::kScout:
      return "scout";
    case TaState::kGoalFounder:
      return "goal_founder";
    case TaState::kDecisionMaker:
      return "decision_maker";
    case TaState::kPathFormation:
      return "path_formation";
    case TaState::kRestingTask:
      return "resting_task";
  }
  return "?";
}

double delta_for(const Params& p, std::uint8_t env_class) {
  switch (env_class) {
    case 0:
      return p.delta_open;
    case 1:
      return p.delta_obstacle;
    default:
      return p.delta_complex;
  }
}

void ta_init(RobotMemory& mem, const Params& p) {
  pf_init(mem.pf, p, PfRole::kScout);
  mem.ta = TaMemory{};
}

namespace {

// the controller's clock: SPEC §1.2's 10 ticks per second (t of Eq. (1) is in seconds)
constexpr double kTicksPerSecond = 10.0;

double seconds(double ticks) { return ticks / kTicksPerSecond; }

// ---- guards ----

bool found_the_goal(const TaContext& c) {  // T2, TA c: the goal within d_detect, no ALLOC_DONE heard
  // a scout going home finds it too [R return_finds]
  return (c.sight.exploring || c.p.return_finds) && c.sight.goal_found && !c.sight.alloc_done_heard;
}

bool allocation_over(const TaContext& c) {  // T7, TA d: late arrivals
  return c.sight.alloc_done_heard || c.sight.path_colour_seen;
}

bool learned_of_the_goal(const TaContext& c) {  // T3, TA f
  // R dm_rescout: a robot whose wait led to no founder is called by a founder's light or REQUEST only
  const bool lights = c.m.rescouted ? c.sight.founder_seen : c.sight.founder_or_dm_seen;
  return lights || c.sight.request_heard;
}

// T6s [R dm_rescout]: a decision maker that has waited T_dm_wait at the nest and never heard a
// REQUEST saw no founder come: the founder may have failed on its way. It scouts again.
bool no_founder_came(const TaContext& c) {
  return c.p.dm_rescout && !c.m.request_ever && static_cast<double>(c.m.waited) >= c.p.t_dm_wait;
}

bool senior_founder(const TaContext& c) {  // T8 [R]: duplicate founders
  return c.sight.senior_founder != kBroadcastId;
}

bool late_founder(const TaContext& c) {  // T7f [R late_founder_rests]: ALLOC_DONE heard before allocating
  return c.p.late_founder_rests && !c.m.protocol_started && c.sight.alloc_done_heard && !c.m.refounder;
}

bool founder_done_and_counts_self(const TaContext& c) {  // T9
  return c.m.protocol_started && c.m.protocol.finished(static_cast<int>(c.p.t_done)) &&
         c.p.founder_counts_self;
}

// T9r: a founder that does not count itself (founder_counts_self false, SPEC row 39) rests when done,
// as a decision maker that was not ACKed does (T6): SPEC's T9 gives it no next state
bool founder_done(const TaContext& c) {
  return c.m.protocol_started && c.m.protocol.finished(static_cast<int>(c.p.t_done));
}

// T10 [R rest_recruit]: a chain's end in view for the robot's wait: the chain ran out of robots
// within sight of the deployment area
bool chain_end_starved(const TaContext& c) {
  return (c.sight.chain_end != nullptr || c.sight.call != nullptr) && c.m.end_seen > 0 &&
         c.m.end_seen >= c.m.end_wait;
}

// T12 [R refound_starved]: the chain's end, unclaimed for T_refound, its call unanswered
bool left_alone(const TaContext& c) { return c.sight.left_alone; }

bool acked(const TaContext& c) { return c.sight.dm.decision == DmDecision::kGo; }  // T5, TA e

bool told_to_rest(const TaContext& c) {  // T6, TA d
  return c.sight.dm.decision == DmDecision::kRest || static_cast<double>(c.m.waited) >= c.p.t_dm_wait;
}

// ---- actions ----

void become_founder(const TaContext& c, RobotMemory& mem) {
  // t: the founder's current minimum exploring time (default) or the ticks of this trip [s]
  const double t_ticks = c.p.t_source == TSource::kBudget
                             ? mem.pf.t_explore
                             : static_cast<double>(c.in.tick - mem.pf.trip_start);
  mem.ta.t_founder_s = seconds(t_ticks);
  if (c.p.route_to_sighting)
    mem.route.keep(mem.trail, c.p.way_home_leg);  // R: the way it found the goal, to lead along
  keep_founder_way(c.p, mem);                     // R lead_way: and to tell
  mem.ta.n = robots_needed(mem.ta.t_founder_s, c.p.v_max, c.p.r_vis, delta_for(c.p, mem.env_class),
                           static_cast<int>(c.p.n_min), c.swarm);
}

// INITIATE_TASK: path formation as an allocated robot, exploring for kappa t_founder (SPEC §2.7)
void start_path_formation(const TaContext& c, RobotMemory& mem, double t_founder_s) {
  const PfMemory keep = mem.pf;  // the founder keeps its sighting of the goal (site fidelity)
  pf_init(mem.pf, c.p, PfRole::kAllocated);
  mem.pf.t_explore = std::max(1.0, c.p.kappa * t_founder_s * kTicksPerSecond);
  mem.pf.sighting = keep.sighting;
  mem.pf.has_sighting = keep.has_sighting;
  if (c.p.lead_way) {  // R: the founder's way, its own or heard at the nest
    mem.pf.knows_way = keep.knows_way;
    mem.pf.tell_count = -1;
    mem.pf.told = keep.told;
  }
  mem.pf.explore_leg = first_leg(c.p, mem.pf);
  mem.pf.trip_start = c.in.tick;
  mem.trail.reset(c.in.pose.p);
}

// guided departure [R]: the founder leads the allocated robots back to the goal
void founder_initiates(const TaContext& c, RobotMemory& mem) {
  start_path_formation(c, mem, mem.ta.t_founder_s);
  if (c.p.guided_departure && mem.pf.explore_leg == ExploreLeg::kToSighting)
    mem.pf.explore_leg = ExploreLeg::kLead;
}

void dm_initiates(const TaContext& c, RobotMemory& mem) {
  const TaMessage& ack = c.sight.dm.ack;
  start_path_formation(c, mem, static_cast<double>(ack.t_founder_ds));
  if (c.p.lead_way && mem.pf.told.teller == ack.id) take_founder_way(mem);  // R: heard whole at the nest
  bool to_sighting = mem.pf.explore_leg == ExploreLeg::kToSighting;
  // R: the robots ACKed later (fewer remaining) leave first, depart_gap ticks apart
  mem.ta.depart_tick = c.in.tick + static_cast<std::int64_t>(std::llround(c.p.depart_gap * ack.remaining));
  if (c.p.share_goal && ack.has_goal()) {
    // R: where the founder saw the goal, relative to the nest: travel there once the guide is lost
    mem.pf.sighting =
        mem.nest + kCm * Vec2{static_cast<double>(ack.goal_x_cm), static_cast<double>(ack.goal_y_cm)};
    mem.pf.has_sighting = true;
    to_sighting = c.p.site_fidelity;
  }
  if (c.p.guided_departure) {
    mem.pf.explore_leg = to_sighting ? ExploreLeg::kFollowThenSighting : ExploreLeg::kFollowThenWalk;
  } else {
    mem.pf.explore_leg = to_sighting ? ExploreLeg::kToSighting : ExploreLeg::kWalk;
  }
}

// T6s [R dm_rescout]: a scout again, its next trip from the nest (as at the start of the run)
void rescout(const TaContext& c, RobotMemory& mem) {
  pf_init(mem.pf, c.p, PfRole::kScout);
  mem.pf.trip_start = c.in.tick;
  mem.trail.reset(c.in.pose.p);
  mem.ta.waited = 0;
  mem.ta.rescouted = true;
}

// T10 [R rest_recruit]: path formation, forming the next link from the chain's end in view
void join_chain_end(const TaContext& c, RobotMemory& mem) {
  start_path_formation(c, mem, seconds(mem.pf.t_explore));
  if (c.sight.chain_end != nullptr) {
    pf_join_chain_end(mem.pf, c.p, *c.sight.chain_end, c.in.pose, mem.nest, c.in.tick);
    return;
  }
  // recruit_call: out of view, where the medium says the caller is; claimed on the way
  const RabMessage& call = *c.sight.call;
  mem.pf.sighting = c.in.pose.p + (call.range_cm / kCmPerM) * c.in.pose.to_world(unit(call.bearing()));
  mem.pf.has_sighting = true;
  mem.pf.explore_leg = ExploreLeg::kToSighting;
  mem.pf.answering = call.sender;
}

// T12 [R refound_starved]: leave the chain's end to its parent (told on the way), home, and found
// the rest of the path there: the place it leaves is where it leads the robots it allocates
void refound(const TaContext& c, RobotMemory& mem) {
  TaMemory& m = mem.ta;
  m.refounder = true;
  m.left_parent = mem.pf.parent.id;
  m.protocol_started = false;
  m.protocol = FounderProtocol{};
  m.n = 0;
  m.nest_best_cm = 1e18;  // founder_in_crowd: a new way to the nest
  m.held = 0;
  mem.pf.sighting = mem.pf.parent.last_seen;
  mem.pf.has_sighting = true;
  mem.pf.trip_start = c.in.tick;
  // its way out to the chain's end, as it came: a back-off that took the trail home from the crumb
  // nearest it among those nearer the nest (start_home_within) may have cut it at a crumb across a wall
  mem.trail.fall_back();
  if (c.p.route_to_sighting)
    mem.route.keep(mem.trail, c.p.way_home_leg);  // R: its way out to the chain's end, to lead along
  keep_founder_way(c.p, mem);                     // R lead_way: and to tell
}

// clang-format off
// SPEC §2.6, in its order; T1 (explore / return / rest) runs inside the scout's path-formation
// states, T4 (the founder at the nest runs the protocol) inside the founder's behaviour. Rows with a
// letter or a number past 9 are [R] (docs/CHOICES.md): T6s dm_rescout (docs/faults.md), T7f
// late_founder_rests, T10 rest_recruit and recruit_call, T11-T12 refound_starved.
constexpr std::array<TaTransition, 13> kTable{{
  {TaState::kScout,         found_the_goal,               TaState::kGoalFounder,   become_founder,    "T2",  "c"},
  {TaState::kScout,         allocation_over,              TaState::kRestingTask,   nullptr,           "T7",  "d"},
  {TaState::kScout,         learned_of_the_goal,          TaState::kDecisionMaker, nullptr,           "T3",  "f"},
  {TaState::kDecisionMaker, acked,                        TaState::kPathFormation, dm_initiates,      "T5",  "e"},
  {TaState::kDecisionMaker, no_founder_came,              TaState::kScout,         rescout,           "T6s", ""},
  {TaState::kDecisionMaker, told_to_rest,                 TaState::kRestingTask,   nullptr,           "T6",  "d"},
  {TaState::kGoalFounder,   senior_founder,               TaState::kDecisionMaker, nullptr,           "T8",  ""},
  {TaState::kGoalFounder,   late_founder,                 TaState::kRestingTask,   nullptr,           "T7f", "d"},
  {TaState::kGoalFounder,   founder_done_and_counts_self, TaState::kPathFormation, founder_initiates, "T9",  "e"},
  {TaState::kGoalFounder,   founder_done,                 TaState::kRestingTask,   nullptr,           "T9r", "d"},
  {TaState::kRestingTask,   chain_end_starved,            TaState::kPathFormation, join_chain_end,    "T10", ""},
  {TaState::kRestingTask,   acked,                        TaState::kPathFormation, dm_initiates,      "T11", "e"},
  {TaState::kPathFormation, left_alone,                   TaState::kGoalFounder,   refound,           "T12", ""},
}};

// clang-format on

constexpr auto kRowsOf = rows_by_state<kTaStateCount>(kTable);
static_assert(kRowsOf.begin[kTaStateCount] == kTable.size(), "a row whose state is out of range");

bool joined(std::uint8_t founder, std::span<const RabMessage> inbox) {
  for (const RabMessage& r : inbox) {
    const TaMessage m = decode(r.data);
    if (m.type == MsgType::kJoin && m.dest == founder) return true;
  }
  return false;
}

// GOAL_FOUNDER (LED cyan): back to the nest (TA c / PF k); there it runs the protocol (T4)
// R founder_in_crowd: a founder before its protocol that the robots waiting at the nest hold off
// (within nest_crowd, a CYAN or GRAY80 light in view, no nearer by trap_progress for T_trap ticks)
bool held_off_the_nest(const Params& p, TaMemory& m, const TaSight& sight) {
  if (!p.founder_in_crowd || m.protocol_started) return false;
  if (sight.nest_distance_cm < m.nest_best_cm - p.trap_progress) {
    m.nest_best_cm = sight.nest_distance_cm;
    m.held = 0;
  } else {
    ++m.held;
  }
  return sight.founder_or_dm_seen && sight.nest_distance_cm <= p.nest_crowd &&
         static_cast<double>(m.held) >= p.t_trap;
}

Command found(const Percept& in, const Params& p, RobotMemory& mem, int swarm, bool at_nest) {
  TaMemory& m = mem.ta;
  const auto id = static_cast<std::uint8_t>(in.id);
  const Command cmd = drive_to(in, p, mem, mem.nest, p.founder_wait * p.r_nest_reach, Led::kCyan,
                               p.founder_retrace && !m.protocol_started);  // R founder_retrace
  if (at_nest && !m.protocol_started) {
    m.protocol_started = true;
    // refound_starved: n from the trip home (Eq. 1-3 with t its time, whatever t_source says, and
    // delta_refound)
    if (m.refounder) {
      m.t_founder_s = seconds(static_cast<double>(in.tick - mem.pf.trip_start));
      m.n = robots_needed(m.t_founder_s, p.v_max, p.r_vis, p.delta_refound, static_cast<int>(p.n_min), swarm);
    }
    m.protocol = start_founder(m.n - (p.founder_counts_self ? 1 : 0));
  }
  if (!m.protocol_started) return m.refounder ? say(cmd, fetch_message(id, m.left_parent)) : cmd;
  Command told = cmd;  // R lead_way: every other tick a corner of its way; the protocol waits a tick
  if (tell_founder_way(in.tick, in.id, p, mem, told)) return told;
  // no JOIN for T_founder_wait ticks: nobody is left to ask; allocate what it has [R]
  m.waited = m.protocol.remaining > 0 && !joined(id, in.rab) ? m.waited + 1 : 0;
  if (p.t_founder_wait > 0.0 && static_cast<double>(m.waited) >= p.t_founder_wait) m.protocol.remaining = 0;
  const auto t = static_cast<std::uint16_t>(std::min(65535.0, std::round(m.t_founder_s)));
  TaMessage msg = founder_tick(m.protocol, id, t, in.rab, p.resend_lost_ack);
  if (p.share_goal && mem.pf.has_sighting) {  // R: its messages (the ACK) tell where it saw the goal
    const Vec2 rel = kCmPerM * (mem.pf.sighting - mem.nest);
    msg.flags = static_cast<std::uint8_t>(msg.flags | kFlagGoal);
    constexpr double kFar = 1e9;  // [cm] far beyond any arena (kMaxArenaSide); encode clamps it
    msg.goal_x_cm = static_cast<std::int32_t>(std::clamp(std::round(rel.x), -kFar, kFar));
    msg.goal_y_cm = static_cast<std::int32_t>(std::clamp(std::round(rel.y), -kFar, kFar));
  }
  if (m.refounder) msg.flags = static_cast<std::uint8_t>(msg.flags | kFlagRecall);
  if (msg.type == MsgType::kDone && m.protocol.done_ticks == 1) {
    m.alloc_done_tick = in.tick;
    m.allocated = m.protocol.acks + (p.founder_counts_self ? 1 : 0);
  }
  return say(cmd, msg);
}

}  // namespace

std::span<const TaTransition> ta_transitions() { return kTable; }

std::uint8_t ta_row_number(std::string_view row) { return row_number(ta_transitions(), row); }

void ta_perceive(const Percept& in, const Params& p, const RobotMemory& mem, TaSight& sight) {
  sight = TaSight{};
  sight.exploring = mem.pf.state == PfState::kExploring;
  sight.nest_distance_cm = kCmPerM * dist(in.pose.p, mem.nest);
  const bool allocating = mem.ta.protocol.acks > 0;
  for (const Blob& b : in.blobs) {
    if (b.emitter == kGoalEmitter && b.distance_cm <= p.d_detect) sight.goal_found = true;
    if (b.emitter >= 0 && (b.color == Led::kCyan || b.color == Led::kGray80)) sight.founder_or_dm_seen = true;
    if (b.emitter >= 0 && b.color == Led::kCyan) sight.founder_seen = true;
    if (b.emitter >= 0 && is_path_colour(b.color)) sight.path_colour_seen = true;  // T7 (not the nest beacon)
  }
  const auto id = static_cast<std::uint8_t>(in.id);
  for (const RabMessage& r : in.rab) {
    const TaMessage m = decode(r.data);
    if (m.type == MsgType::kRequest || m.type == MsgType::kAck) sight.request_heard = true;
    if (m.type == MsgType::kDone || m.alloc_done()) sight.alloc_done_heard = true;
  }
  // (each read of the inbox only in the states whose rows use it: T8 a founder's, T11 a resting robot's)
  if (mem.ta.state == TaState::kGoalFounder)
    sight.senior_founder = senior_founder_heard({allocating, id}, in.rab, p.founder_seniority);
  if (mem.ta.state != TaState::kRestingTask) sight.dm = decision_maker_tick(id, in.rab, p.founder_seniority);
  // rest_recruit: only at its deployment point (robots passing by can push a resting one far off)
  if (p.rest_recruit && mem.ta.state == TaState::kRestingTask && mem.ta.arrived &&
      kCmPerM * dist(in.pose.p, mem.start) <= p.d_detect) {
    sight.chain_end = free_subgoal_in_view(in);
    if (sight.chain_end == nullptr && p.recruit_call) sight.call = unanswered_call(in.rab);
  }
  // a resting robot answers only a second allocation (refound_starved, T11), at its deployment point
  if (mem.ta.state == TaState::kRestingTask)
    sight.dm = p.refound_starved && mem.ta.arrived ? resting_tick(id, in.rab, p.founder_seniority) : DmTick{};
  const PfMemory& pf = mem.pf;
  sight.left_alone = p.refound_starved && mem.ta.state == TaState::kPathFormation && calls_links(p, pf) &&
                     pf.state == PfState::kSubgoal && pf.parent.valid() &&
                     static_cast<double>(pf.unclaimed) >= p.t_refound && in.tick >= pf.help_until;
}

const TaTransition* ta_transition(const TaContext& c, RobotMemory& mem) {
  for (const std::size_t i : kRowsOf.of(static_cast<std::size_t>(mem.ta.state))) {
    const TaTransition& row = kTable[i];
    if (!row.when(c)) continue;
    if (row.act != nullptr) row.act(c, mem);
    mem.ta.state = row.to;
    mem.ta.t_state = 0;
    mem.ta.waited = 0;
    mem.ta.last_row = static_cast<std::uint8_t>(i + 1);
    mem.ta.fired_tick = c.in.tick;
    return &row;
  }
  return nullptr;
}

RabKinds ta_interest(const Params& p, const RobotMemory& mem) {
  switch (mem.ta.state) {
    case TaState::kScout:        // every reading: T2 (a founder reads JOINs), T3, T7, path formation
    case TaState::kGoalFounder:  // T8, T7f, T9 (path formation), the protocol (JOINs)
      return kEveryRabKind;
    case TaState::kDecisionMaker:  // the protocol; T5 may start path formation this tick (claims, fetches);
                                   // lead_way's corners
      return kKindFounder | kKindAllocDone | kKindClaim | kKindFetch | (p.lead_way ? kKindWay : 0);
    case TaState::kPathFormation:  // path formation's claims and fetches; T12 (a founder reads JOINs);
                                   // lead_way's corners
      return kKindClaim | kKindFetch | kKindJoin | (p.lead_way ? kKindWay : 0);
    case TaState::kRestingTask:  // at its deployment point: T10's claims and calls, T11's recalls, and
                                 // path formation after them
      return mem.ta.arrived && (p.rest_recruit || p.refound_starved) ? kKindClaim | kKindFetch | kKindRecall
                                                                     : 0;
  }
  return kEveryRabKind;
}

Command task_allocation_step(const Percept& in, const Params& p, RobotMemory& mem, int swarm) {
  TaMemory& m = mem.ta;
  TaSight sight;
  ta_perceive(in, p, mem, sight);
  if (listens_for_founder_way(p, mem, in.tick)) hear_founder_way(in.rab, mem);  // lead_way [R]
  if (sight.chain_end == nullptr && sight.call == nullptr) {
    m.end_seen = 0;
  } else if (m.end_seen++ == 0) {  // R rest_recruit: T_recruit plus a draw, so that one of several goes
    const auto extra = static_cast<std::uint64_t>(std::max(0.0, std::round(p.t_recruit)));
    m.end_wait = static_cast<std::int64_t>(extra + mem.rng.below(extra + 1));
  }
  const TaContext c{in, p, m, sight, swarm};
  if (ta_transition(c, mem) != nullptr) nav_reset(mem.nav);
  ++m.t_state;
  const bool at_nest = sight.nest_distance_cm <= p.r_nest_reach;
  const bool held_off = m.state == TaState::kGoalFounder && held_off_the_nest(p, m, sight);

  Command cmd;
  switch (m.state) {
    case TaState::kScout:  // exploring, returning, resting: path formation's rows #2-#4 (TA a, b)
      cmd = path_formation_step(in, p, mem);
      break;
    case TaState::kPathFormation:     // allocated (TA e): path formation
      if (in.tick < m.depart_tick) {  // R: waiting its turn to leave (depart_gap)
        cmd = drive_to(in, p, mem, mem.nest, p.nest_wait * p.r_nest_reach, Led::kGray80);
        mem.trail.reset(in.pose.p);
        break;
      }
      cmd = path_formation_step(in, p, mem);
      if (mem.pf.explore_leg == ExploreLeg::kLead && !cmd.rab_send)
        tell_founder_way(in.tick, in.id, p, mem, cmd);
      break;
    case TaState::kGoalFounder:
      cmd = found(in, p, mem, swarm, at_nest || held_off);
      break;
    case TaState::kDecisionMaker:
      // gather at the nest; answer a requesting founder with JOIN
      cmd = drive_to(in, p, mem, mem.nest, p.nest_wait * p.r_nest_reach, Led::kGray80);
      m.waited = (at_nest && !sight.request_heard) ? m.waited + 1 : 0;
      m.request_ever = m.request_ever || sight.request_heard;
      if (sight.dm.send.type == MsgType::kJoin) cmd = say(cmd, sight.dm.send);
      break;
    case TaState::kRestingTask:
      cmd = rest(in, p, mem, sight);
      break;
  }
  mem.state = static_cast<std::uint8_t>(static_cast<int>(m.state) * 16 + static_cast<int>(mem.pf.state));
  return cmd;
}

}  // namespace swarmpath::sim
