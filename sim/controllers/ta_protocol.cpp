// SPDX-License-Identifier: MIT
#include "ta_protocol.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "rab_bytes.hpp"

namespace swarmpath::sim {

namespace {

using detail::kGoalUnits;

// x / unit rounded half away from zero
std::int64_t goal_steps(std::int32_t x_cm, std::int32_t unit) {
  const std::int64_t q = (std::abs(std::int64_t{x_cm}) + unit / 2) / unit;
  return x_cm < 0 ? -q : q;
}

// the finest unit (1, 10, 100 cm) in which both coordinates fit 12 signed bits; beyond +-2 047 m the
// coarsest, clamped
int goal_unit_exponent(std::int32_t x_cm, std::int32_t y_cm) {
  int e = 0;
  const auto fits = [&e](std::int32_t v) { return std::abs(goal_steps(v, kGoalUnits[e])) <= kGoalMaxSteps; };
  while (e < 2 && !(fits(x_cm) && fits(y_cm))) ++e;
  return e;
}

std::uint32_t goal_bits(std::int32_t v_cm, int e) {
  const std::int64_t max = kGoalMaxSteps;
  return static_cast<std::uint32_t>(std::clamp(goal_steps(v_cm, kGoalUnits[e]), -max, max)) & 0xfff;
}

}  // namespace

RabPayload encode(const TaMessage& m) {
  static_assert(kRabPayloadBytes == 10, "SPEC §2.6: the payload is 10 bytes");
  RabPayload p{};
  p[0] = m.id;
  p[1] = m.state;
  p[2] = m.parent;
  p[3] = static_cast<std::uint8_t>(m.flags & ~kGoalUnitMask);
  p[4] = static_cast<std::uint8_t>(m.type);
  p[5] = m.dest;
  p[6] = m.remaining;
  p[8] = static_cast<std::uint8_t>(m.t_founder_ds >> 8);
  p[9] = static_cast<std::uint8_t>(m.t_founder_ds & 0xff);
  if (!founder_message(m.type)) {
    p[3] = static_cast<std::uint8_t>(p[3] & ~kFlagGoal);  // only a founder message has room for it
    return p;
  }
  // R: a founder message has no state or parent byte: bytes 1, 2 and 7 carry its goal sighting
  p[1] = 0;
  p[2] = 0;
  if (!m.has_goal()) return p;
  const int e = goal_unit_exponent(m.goal_x_cm, m.goal_y_cm);
  const std::uint32_t x = goal_bits(m.goal_x_cm, e);
  const std::uint32_t y = goal_bits(m.goal_y_cm, e);
  p[1] = static_cast<std::uint8_t>(x >> 4);
  p[2] = static_cast<std::uint8_t>(y >> 4);
  p[7] = static_cast<std::uint8_t>(((x & 0xf) << 4) | (y & 0xf));
  p[3] = static_cast<std::uint8_t>(p[3] | (e << kGoalUnitShift));
  return p;
}

FounderProtocol start_founder(int robots) {
  FounderProtocol f;
  f.remaining = std::max(0, robots);
  return f;
}

TaMessage founder_tick(FounderProtocol& f, std::uint8_t my_id, std::uint16_t t_founder_ds,
                       std::span<const RabMessage> inbox, bool resend_lost_ack) {
  TaMessage out;
  out.id = my_id;
  out.state = kFounderState;  // implied by the message type on the medium
  out.t_founder_ds = t_founder_ds;
  // the nearest JOIN addressed to me (once no robot is needed: from a robot already ACKed, whose
  // ACK was lost); ties go to the smaller id
  const RabMessage* best = nullptr;
  std::uint8_t best_id = 0;
  for (const RabMessage& r : inbox) {
    const TaMessage m = decode(r.data);
    if (m.type != MsgType::kJoin || m.dest != my_id) continue;
    if (f.is_acked(m.id) ? !resend_lost_ack : f.remaining == 0) continue;
    if (best == nullptr || r.range_cm < best->range_cm || (r.range_cm == best->range_cm && m.id < best_id)) {
      best = &r;
      best_id = m.id;
    }
  }
  if (best != nullptr) {
    out.type = MsgType::kAck;
    out.dest = best_id;
    if (!f.is_acked(best_id)) {  // a repeated JOIN (its ACK was lost) is answered, not counted
      f.acked.insert(best_id);
      ++f.acks;
      --f.remaining;
    }
  } else if (f.remaining == 0) {
    out.type = MsgType::kDone;
    out.flags = kFlagAllocDone;
    ++f.done_ticks;
  } else {
    out.type = MsgType::kRequest;
  }
  if (f.acks > 0) out.flags = static_cast<std::uint8_t>(out.flags | kFlagAllocating);
  out.remaining = static_cast<std::uint8_t>(std::min(f.remaining, 255));  // R: one byte (ids are one byte)
  return out;
}

bool outranks(FounderRank a, FounderRank b, bool seniority) {
  if (seniority && a.allocating != b.allocating) return a.allocating;
  return a.id < b.id;
}

namespace {

bool from_founder(const TaMessage& m) { return m.type == MsgType::kRequest || m.type == MsgType::kAck; }

}  // namespace

std::uint8_t senior_founder_heard(FounderRank me, std::span<const RabMessage> inbox, bool seniority) {
  FounderRank best = me;
  for (const RabMessage& r : inbox) {
    const TaMessage m = decode(r.data);
    const FounderRank them{m.allocating(), m.id};
    if (from_founder(m) && m.id != me.id && outranks(them, best, seniority)) best = them;
  }
  return best.id == me.id ? kBroadcastId : best.id;
}

namespace {

// a decision maker's tick; `resting`: a resting robot's, which hears only founders allocating from
// the resting robots (kFlagRecall) and no DONE
DmTick answer_founders(std::uint8_t my_id, std::span<const RabMessage> inbox, bool seniority, bool resting) {
  DmTick out;
  FounderRank founder;
  bool done = false;
  for (const RabMessage& r : inbox) {
    const TaMessage m = decode(r.data);
    if (resting && !m.recall()) continue;
    if (m.type == MsgType::kAck && m.dest == my_id) {
      out.decision = DmDecision::kGo;
      out.ack = m;
      return out;
    }
    if (!resting && (m.type == MsgType::kDone || m.alloc_done())) done = true;
    const FounderRank them{m.allocating(), m.id};
    if (from_founder(m) && outranks(them, founder, seniority)) founder = them;  // unset: id 255
  }
  if (done) {
    out.decision = DmDecision::kRest;
    return out;
  }
  if (founder.id != kBroadcastId) {
    out.send.id = my_id;
    out.send.type = MsgType::kJoin;
    out.send.dest = founder.id;
  }
  return out;
}

}  // namespace

DmTick decision_maker_tick(std::uint8_t my_id, std::span<const RabMessage> inbox, bool seniority) {
  return answer_founders(my_id, inbox, seniority, false);
}

DmTick resting_tick(std::uint8_t my_id, std::span<const RabMessage> inbox, bool seniority) {
  return answer_founders(my_id, inbox, seniority, true);
}

namespace {

// a message naming a robot or the goal in its parent byte (a claim, a fetch)
TaMessage naming(std::uint8_t my_id, std::uint8_t state, int emitter) {
  TaMessage m;
  m.id = my_id;
  m.state = state;
  m.parent = emitter == kGoalEmitter ? kGoalRabId : static_cast<std::uint8_t>(emitter);
  return m;
}

int named_emitter(const TaMessage& m) {
  if (m.type != MsgType::kNone || m.parent == kBroadcastId) return kNobody;
  return m.parent == kGoalRabId ? kGoalEmitter : static_cast<int>(m.parent);
}

}  // namespace

TaMessage claim_message(std::uint8_t my_id, int emitter) { return naming(my_id, kClaimState, emitter); }

int claimed_emitter(const TaMessage& m) { return m.state == kClaimState ? named_emitter(m) : kNobody; }

TaMessage fetch_message(std::uint8_t my_id, int parent) {
  TaMessage m = naming(my_id, kFetchState, parent);
  m.flags = kFlagFetch;
  return m;
}

int fetch_for(const TaMessage& m) { return m.fetch() && m.state == kFetchState ? named_emitter(m) : kNobody; }

RabPayload way_message(std::uint8_t id, const WayCorner& c) {
  RabPayload p{};
  p[0] = id;
  p[2] = static_cast<std::uint8_t>(c.index);
  p[4] = static_cast<std::uint8_t>(MsgType::kWay);
  p[5] = static_cast<std::uint8_t>(c.count);
  const std::uint8_t e = put_position_cm(p, 6, c.x_cm, c.y_cm);
  p[3] = static_cast<std::uint8_t>(e << kGoalUnitShift);  // in the goal's unit bits: flags stay 0
  return p;
}

WayCorner way_corner(const RabPayload& p) {
  WayCorner c{p[2], p[5], 0.0, 0.0};
  get_position_cm(p, 6, static_cast<std::uint8_t>((p[3] & kGoalUnitMask) >> kGoalUnitShift), c.x_cm, c.y_cm);
  return c;
}

RabKinds message_kinds(const TaMessage& m) {
  RabKinds k = 0;
  if (founder_message(m.type)) k |= kKindFounder;
  if (m.alloc_done()) k |= kKindAllocDone;
  if (m.type == MsgType::kJoin) k |= kKindJoin;
  if (claimed_emitter(m) != kNobody) k |= kKindClaim;
  if (fetch_for(m) != kNobody) k |= kKindFetch;
  if (m.recall()) k |= kKindRecall;
  if (m.type == MsgType::kWay) k |= kKindWay;
  return k;
}

int robots_needed(double t_seconds, double speed_cm_s, double r_vis_cm, double delta, int n_min, int swarm) {
  const double l = speed_cm_s * t_seconds;                       // Eq. (1)
  const double n0 = l / r_vis_cm;                                // Eq. (2)
  const int n = static_cast<int>(std::ceil(n0 + delta - 1e-9));  // Eq. (3), rounded up
  return std::clamp(n, n_min, swarm);
}

}  // namespace swarmpath::sim
