// SPDX-License-Identifier: MIT
#include "ta_protocol.hpp"

#include <algorithm>
#include <cmath>

namespace swarmpath::sim {

RabPayload encode(const TaMessage& m) {
  RabPayload p{};
  p[0] = m.id;
  p[1] = m.state;
  p[2] = m.parent;
  p[3] = m.flags;
  p[4] = static_cast<std::uint8_t>(m.type);
  p[5] = m.dest;
  p[6] = static_cast<std::uint8_t>(m.remaining >> 8);
  p[7] = static_cast<std::uint8_t>(m.remaining & 0xff);
  p[8] = static_cast<std::uint8_t>(m.t_founder_ds >> 8);
  p[9] = static_cast<std::uint8_t>(m.t_founder_ds & 0xff);
  const auto gx = static_cast<std::uint16_t>(m.goal_x_cm);
  const auto gy = static_cast<std::uint16_t>(m.goal_y_cm);
  p[10] = static_cast<std::uint8_t>(gx >> 8);
  p[11] = static_cast<std::uint8_t>(gx & 0xff);
  p[12] = static_cast<std::uint8_t>(gy >> 8);
  p[13] = static_cast<std::uint8_t>(gy & 0xff);
  return p;
}

TaMessage decode(const RabPayload& p) {
  TaMessage m;
  m.id = p[0];
  m.state = p[1];
  m.parent = p[2];
  m.flags = p[3];
  m.type = p[4] <= 4 ? static_cast<MsgType>(p[4]) : MsgType::kNone;
  m.dest = p[5];
  m.remaining = static_cast<std::uint16_t>((p[6] << 8) | p[7]);
  m.t_founder_ds = static_cast<std::uint16_t>((p[8] << 8) | p[9]);
  m.goal_x_cm = static_cast<std::int16_t>(static_cast<std::uint16_t>((p[10] << 8) | p[11]));
  m.goal_y_cm = static_cast<std::int16_t>(static_cast<std::uint16_t>((p[12] << 8) | p[13]));
  return m;
}

FounderProtocol start_founder(int robots) {
  FounderProtocol f;
  f.remaining = std::max(0, robots);
  return f;
}

TaMessage founder_tick(FounderProtocol& f, std::uint8_t my_id, std::uint16_t t_founder_ds,
                       std::span<const RabMessage> inbox) {
  TaMessage out;
  out.id = my_id;
  out.t_founder_ds = t_founder_ds;
  // the nearest JOIN addressed to me (once no robot is needed: from a robot already ACKed, whose
  // ACK was lost); ties go to the smaller id
  const RabMessage* best = nullptr;
  std::uint8_t best_id = 0;
  for (const RabMessage& r : inbox) {
    const TaMessage m = decode(r.data);
    if (m.type != MsgType::kJoin || m.dest != my_id) continue;
    if (f.remaining == 0 && !f.is_acked(m.id)) continue;
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
  out.remaining = static_cast<std::uint16_t>(f.remaining);
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

int robots_needed(double t_seconds, double speed_cm_s, double r_vis_cm, double delta, int n_min, int swarm) {
  const double l = speed_cm_s * t_seconds;                       // Eq. (1)
  const double n0 = l / r_vis_cm;                                // Eq. (2)
  const int n = static_cast<int>(std::ceil(n0 + delta - 1e-9));  // Eq. (3), rounded up
  return std::clamp(n, n_min, swarm);
}

}  // namespace swarmpath::sim
