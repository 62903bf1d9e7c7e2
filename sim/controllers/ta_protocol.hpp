// SPDX-License-Identifier: MIT
// The task-allocation protocol over the range-and-bearing medium (paper, "Local Communication
// Protocol"; SPEC §2.6): the goal founder broadcasts REQUEST, decision makers answer JOIN, the
// founder ACKs one JOIN per tick (the nearest) and counts down the robots it still needs, then
// broadcasts DONE. Pure functions of the messages heard, so that the protocol can be tested with
// a scripted medium that loses or delays messages.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "sim/percept.hpp"

namespace swarmpath::sim {

/// kWay [R lead_way]: one corner of a founder's way to the goal (way_message), not of SPEC §2.6
enum class MsgType : std::uint8_t { kNone = 0, kRequest = 1, kJoin = 2, kAck = 3, kDone = 4, kWay = 5 };

inline constexpr std::uint8_t kBroadcastId = 255;   ///< destination "all" / parent "none"
inline constexpr std::uint8_t kFlagAllocDone = 1;   ///< flags bit 0: the allocation is over
inline constexpr std::uint8_t kFlagGoal = 2;        ///< flags bit 1: a founder message holds the goal [R]
inline constexpr std::uint8_t kFlagAllocating = 4;  ///< flags bit 2: this founder has ACKed a robot [R]
inline constexpr std::uint8_t kFlagNeed = 8;  ///< flags bit 3: a subgoal calls for a link (recruit_call) [R]
/// flags bit 4: a founder allocating from the resting robots (refound_starved) [R]
inline constexpr std::uint8_t kFlagRecall = 16;
/// flags bit 5: a chain's end leaving to fetch robots; parent byte: the subgoal it leaves (refound_starved)
/// [R]
inline constexpr std::uint8_t kFlagFetch = 32;
/// flags bits 6-7 on the medium [R]: the unit of the goal sighting, 10^e cm (encode sets them, decode
/// takes them off; TaMessage::flags never holds them)
inline constexpr std::uint8_t kGoalUnitShift = 6;
inline constexpr std::uint8_t kGoalUnitMask = 0xc0;
inline constexpr std::int32_t kGoalMaxSteps = 2047;  ///< a goal coordinate travels in 12 signed bits
inline constexpr int kMaxTaRobots = 254;             ///< ids travel in one byte
inline constexpr std::uint8_t kClaimState = 3;  ///< state byte of a claim: TaState::kPathFormation (asserted)
/// TaState::kGoalFounder (asserted): the state a founder message (founder_message) implies
inline constexpr std::uint8_t kFounderState = 1;
inline constexpr std::uint8_t kFetchState = kFounderState;  ///< state byte of a fetch message (a founder's)

/// REQUEST, ACK and DONE: the messages only a founder sends (founder_tick).
constexpr bool founder_message(MsgType t) {
  return t == MsgType::kRequest || t == MsgType::kAck || t == MsgType::kDone;
}

/// SPEC §2.6 framing of the 10-byte payload (kRabPayloadBytes): 0 id; 1 state; 2 parent id (255 none);
/// 3 flags (bit 0 ALLOC_DONE; [R] bit 1 goal, bit 2 allocating, bit 3 a subgoal calling for a link, bit 4
/// a founder allocating from the resting robots, bit 5 a chain's end leaving to fetch robots, bits 6-7 the
/// goal's unit); 4 message type; 5 destination id (255 all); 6 remaining ([R] one byte: it counts robots,
/// whose ids are one byte; SPEC 6-7); 7 [R] the goal's low bits; 8-9 t_founder/10.
/// [R] A founder message (founder_message) carries no state (its type says GOAL_FOUNDER) and no parent,
/// so bytes 1, 2 and 7 carry the founder's goal sighting relative to the nest (flags bit 1): x and y as
/// 12-bit signed counts of 10^e cm (bytes 1 and 2 their high 8 bits, byte 7 their low 4 bits, x's first),
/// e = flags bits 6-7 the finest of 1, 10, 100 cm in which both fit (+-20.47 m, +-204.7 m, +-2 047 m:
/// the paper's arenas travel to the centimetre, any arena of kMaxArenaSide to the metre).
struct TaMessage {
  std::uint8_t id = 0;
  std::uint8_t state = 0;
  std::uint8_t parent = kBroadcastId;
  std::uint8_t flags = 0;
  MsgType type = MsgType::kNone;
  std::uint8_t dest = kBroadcastId;
  std::uint8_t remaining = 0;
  std::uint16_t t_founder_ds = 0;  ///< the founder's t [s] (its t in ticks / 10, SPEC "t_founder/10")
  std::int32_t goal_x_cm = 0;  ///< the goal sighting relative to the nest [cm] (founder messages, kFlagGoal)
  std::int32_t goal_y_cm = 0;

  bool alloc_done() const { return (flags & kFlagAllocDone) != 0; }

  bool has_goal() const { return (flags & kFlagGoal) != 0; }

  bool allocating() const { return (flags & kFlagAllocating) != 0; }

  bool needs_link() const { return (flags & kFlagNeed) != 0; }

  bool recall() const { return (flags & kFlagRecall) != 0; }

  bool fetch() const { return (flags & kFlagFetch) != 0; }
};

/// The kinds of TA message (RabKinds bits), one for each way a reader of the inbox picks messages:
/// a reader looks only at messages of the kinds it names in ta_interest.
inline constexpr RabKinds kKindFounder = 1;    ///< REQUEST, ACK, DONE (founder_message)
inline constexpr RabKinds kKindAllocDone = 2;  ///< the ALLOC_DONE flag
inline constexpr RabKinds kKindJoin = 4;       ///< JOIN
inline constexpr RabKinds kKindClaim = 8;      ///< a claim (claimed_emitter), recruit_call's too
inline constexpr RabKinds kKindFetch = 16;     ///< a fetch message (fetch_for)
inline constexpr RabKinds kKindRecall = 32;    ///< a founder allocating from the resting robots
inline constexpr RabKinds kKindWay = 64;       ///< a corner of a founder's way (lead_way)

/// A set of robot ids as they travel on the medium (one byte each).
struct IdSet {
  std::array<std::uint64_t, 4> bits{};

  void insert(std::uint8_t id) { bits[id / 64] |= std::uint64_t{1} << (id % 64); }

  bool contains(std::uint8_t id) const { return ((bits[id / 64] >> (id % 64)) & 1u) != 0; }
};

RabPayload encode(const TaMessage& m);

namespace detail {

inline constexpr std::int32_t kGoalUnits[4] = {1, 10, 100, 1000};  ///< flags bits 6-7: 10^e cm

/// a 12-bit two's-complement count
constexpr std::int32_t sign_extend_12(std::uint32_t v) {
  return static_cast<std::int32_t>(v & 0x7ff) - ((v & 0x800) != 0 ? 2048 : 0);
}

}  // namespace detail

/// The inverse of encode. Inline: every robot decodes every message it hears several times a tick,
/// each reader for a few fields, and the compiler keeps only those.
inline TaMessage decode(const RabPayload& p) {
  TaMessage m;
  m.id = p[0];
  m.state = p[1];
  m.parent = p[2];
  m.flags = static_cast<std::uint8_t>(p[3] & ~kGoalUnitMask);
  m.type = p[4] <= 5 ? static_cast<MsgType>(p[4]) : MsgType::kNone;
  m.dest = p[5];
  m.remaining = p[6];
  m.t_founder_ds = static_cast<std::uint16_t>((p[8] << 8) | p[9]);
  if (!founder_message(m.type)) {
    m.flags = static_cast<std::uint8_t>(m.flags & ~kFlagGoal);
    return m;
  }
  m.state = kFounderState;  // R: the state a founder message implies; it names no parent
  m.parent = kBroadcastId;
  if (!m.has_goal()) return m;
  const std::int32_t unit = detail::kGoalUnits[(p[3] & kGoalUnitMask) >> kGoalUnitShift];
  m.goal_x_cm = unit * detail::sign_extend_12((static_cast<std::uint32_t>(p[1]) << 4) | (p[7] >> 4));
  m.goal_y_cm = unit * detail::sign_extend_12((static_cast<std::uint32_t>(p[2]) << 4) | (p[7] & 0xf));
  return m;
}

/// The founder's side. One tick at a time: it reads the JOINs addressed to it and returns what it
/// broadcasts.
struct FounderProtocol {
  int remaining = 0;   ///< ACKs still to send
  int acks = 0;        ///< distinct robots ACKed so far (the allocation, the founder aside)
  int done_ticks = 0;  ///< ticks DONE has been broadcast
  IdSet acked;         ///< ids ACKed (a robot is never counted twice)

  bool is_acked(std::uint8_t id) const { return acked.contains(id); }

  /// Finished: every robot ACKed and DONE broadcast for `done_for` ticks.
  bool finished(int done_for) const { return remaining == 0 && done_ticks >= done_for; }
};

/// Starts a founder that needs `robots` more robots (n minus itself when it counts itself).
FounderProtocol start_founder(int robots);

/// One founder tick: the nearest JOIN addressed to it (ties: the smaller id) gets the ACK. A JOIN
/// from a robot already ACKed (its ACK was lost) is ACKed again without counting it again, also
/// after the count has reached zero, so that a lost ACK does not leave a counted robot behind.
/// Without a JOIN it repeats REQUEST; once no robot is needed, it broadcasts DONE.
/// `resend_lost_ack` off: a JOIN from a robot already ACKed is ignored.
TaMessage founder_tick(FounderProtocol& f, std::uint8_t my_id, std::uint16_t t_founder_ds,
                       std::span<const RabMessage> inbox, bool resend_lost_ack = true);

/// What a decision maker does this tick.
enum class DmDecision : std::uint8_t { kWait, kGo, kRest };

struct DmTick {
  DmDecision decision = DmDecision::kWait;
  TaMessage send;  ///< JOIN when a founder is requesting
  TaMessage ack;   ///< the ACK addressed to this robot (its t_founder, goal sighting), with kGo
};

/// Which of two duplicate founders wins (SPEC §2.6 T8): the smaller id; with `seniority` [R], a
/// founder that has ACKed robots (kFlagAllocating) first, so that a late founder with a smaller id
/// does not start a second allocation beside it.
struct FounderRank {
  bool allocating = false;
  std::uint8_t id = kBroadcastId;
};

bool outranks(FounderRank a, FounderRank b, bool seniority);

/// One decision-maker tick: an ACK addressed to it -> go (INITIATE_TASK); DONE or ALLOC_DONE
/// heard -> rest; a founder requesting (REQUEST, or ACKs to others) -> JOIN the founder that
/// ranks first (outranks).
DmTick decision_maker_tick(std::uint8_t my_id, std::span<const RabMessage> inbox, bool seniority = false);

/// refound_starved [R]: a resting robot's tick. It answers only founders that allocate from the resting
/// robots (REQUEST or ACK with kFlagRecall): an ACK addressed to it -> go; else JOIN the founder that
/// ranks first. DONE and the other resting robots' ALLOC_DONE flags do not concern it (it rests anyway).
DmTick resting_tick(std::uint8_t my_id, std::span<const RabMessage> inbox, bool seniority = false);

/// refound_starved [R]: the message a chain's end sends as it leaves to fetch robots (kFlagFetch, the
/// subgoal it leaves in the parent byte; not a claim).
TaMessage fetch_message(std::uint8_t my_id, int parent);

/// The robot a fetch message names (fetch_message), or kNobody.
int fetch_for(const TaMessage& m);

/// single_child [R]: an allocated robot forming from, or chained to, `emitter` (a robot id or
/// kGoalEmitter) says so on the medium: parent byte = the robot's id, or kGoalRabId for the goal.
inline constexpr std::uint8_t kGoalRabId = 254;
TaMessage claim_message(std::uint8_t my_id, int emitter);

/// The emitter a message claims (claim_message), or kNobody.
int claimed_emitter(const TaMessage& m);

/// lead_way [R]: corner `index` of `count` of a founder's way to the goal, relative to the nest [cm].
struct WayCorner {
  int index = 0;
  int count = 0;
  double x_cm = 0;
  double y_cm = 0;
};

/// lead_way [R]: the payload of a corner: 0 id, 1 state 0 (no claim), 2 the index, 3 flags 0 with the
/// unit in the goal's unit bits, 4 kWay, 5 the count, 6-7 and 8-9 x and y (rab_bytes.hpp: signed
/// 16-bit in 10^e cm, the centimetre within 327 m of the nest).
RabPayload way_message(std::uint8_t id, const WayCorner& c);

/// The corner a kWay payload carries (way_message's inverse).
WayCorner way_corner(const RabPayload& p);

/// The kinds (kKind*) of message `m` is.
RabKinds message_kinds(const TaMessage& m);

/// Calls f(sender, emitter) for every claim on the medium this tick (claim_message), whoever sends it.
template <typename F>
void for_each_claim_heard(std::span<const RabMessage> inbox, F&& f) {
  for (const RabMessage& r : inbox) {
    const int named = claimed_emitter(decode(r.data));
    if (named != kNobody) f(r.sender, named);
  }
}

/// The founder that wins among duplicates: a REQUEST (or ACK) heard from a founder that outranks
/// `me` (SPEC §2.6 T8); returns its id or kBroadcastId.
std::uint8_t senior_founder_heard(FounderRank me, std::span<const RabMessage> inbox, bool seniority = false);

/// The ALLOC_DONE flag a robot out of the allocation broadcasts (SPEC §2.6 T6), in TA state `state`.
inline TaMessage alloc_done_message(std::uint8_t my_id, std::uint8_t state) {
  TaMessage m;
  m.id = my_id;
  m.state = state;
  m.flags = kFlagAllocDone;
  return m;
}

/// `cmd` with `m` on the medium this tick.
inline Command say(Command cmd, const TaMessage& m) {
  cmd.rab_send = true;
  cmd.rab = encode(m);
  return cmd;
}

/// SPEC §2.7: n = ceil(l/v + delta) clamped to [n_min, N], l = s t [cm], v = R_vis [cm].
int robots_needed(double t_seconds, double speed_cm_s, double r_vis_cm, double delta, int n_min, int swarm);

}  // namespace swarmpath::sim
