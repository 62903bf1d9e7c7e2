// SPDX-License-Identifier: MIT
#include "sighting_share.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "rab_bytes.hpp"
#include "units.hpp"

namespace swarmpath::sim {

namespace {

// payload: byte 0 the sender's id, byte 1 this mark, bytes 2-5 and 6-9 the sighting's x and y
// relative to the nest in cm (signed 32-bit, little-endian).
constexpr std::uint8_t kSightingMark = 0x53;
// share_way: byte 0 the sender's id, byte 1 this mark, byte 2 the corner's index, byte 3 how many
// corners, bytes 4-5 and 6-7 the corner's x and y relative to the nest in cm (signed 16-bit,
// little-endian: 327 m either way). Path formation sends no other message.
constexpr std::uint8_t kWayMark = 0x57;

}  // namespace

bool may_tell(const Params& p, const PfMemory& m, std::int64_t tick) {
  if (p.share_after_trips > 0.0) return static_cast<double>(m.fruitless_trips) >= p.share_after_trips;
  return static_cast<double>(tick) >= p.share_after;
}

bool tells_sighting(const Params& p, const PfMemory& m, double nest_distance_cm, std::int64_t tick) {
  return p.share_sighting > 0.0 && may_tell(p, m, tick) && m.role == PfRole::kSwarm && m.has_sighting &&
         (!p.share_way || (m.knows_way && m.tell_count > 0)) && nest_distance_cm <= p.share_sighting &&
         (m.state == PfState::kResting || m.state == PfState::kReturnToNest ||
          m.state == PfState::kExploring);
}

bool listens_for_sighting(const Params& p, const PfMemory& m, std::int64_t tick) {
  // what is heard at `tick` was told at tick - 1; a robot's own trips are its own condition
  const std::int64_t told_at = p.share_after_trips > 0.0 ? tick : tick - 1;
  return p.share_sighting > 0.0 && may_tell(p, m, told_at) && m.role == PfRole::kSwarm &&
         m.state == PfState::kResting && !m.has_sighting;
}

void tell_sighting(int id, Vec2 nest, const PfMemory& m, Command& cmd) {
  const Vec2 rel = kCmPerM * (m.sighting - nest);
  cmd.rab_send = true;
  cmd.rab = RabPayload{};
  cmd.rab[0] = static_cast<std::uint8_t>(id & 0xff);
  cmd.rab[1] = kSightingMark;
  put_i32(cmd.rab, 2, static_cast<std::int32_t>(std::lround(rel.x)));
  put_i32(cmd.rab, 6, static_cast<std::int32_t>(std::lround(rel.y)));
}

bool hear_sighting(std::span<const RabMessage> inbox, Vec2 nest, PfMemory& m) {
  const RabMessage* best = nullptr;
  for (const RabMessage& r : inbox) {
    if (r.data[1] != kSightingMark) continue;
    if (best == nullptr || r.range_cm < best->range_cm ||
        (r.range_cm == best->range_cm && r.sender < best->sender))
      best = &r;
  }
  if (best == nullptr) return false;
  const Vec2 rel{static_cast<double>(get_i32(best->data, 2)), static_cast<double>(get_i32(best->data, 6))};
  m.sighting = nest + kCm * rel;
  m.has_sighting = true;
  m.sighted_this_trip = false;
  m.knows_way = false;
  m.told = ToldWay{};
  m.told.teller = best->sender;
  return true;
}

void work_out_way(const Params& p, const Route& route, PfMemory& m) {
  if ((!p.share_way && !p.lead_way) || !m.knows_way) return;
  if (m.tell_count < 0 || m.tell_for.x != m.sighting.x || m.tell_for.y != m.sighting.y) {
    m.tell_count = route.corners(m.sighting, p.r_vis * kCm + kWaySlack, m.tell_corners);
    m.tell_for = m.sighting;
  }
}

bool corner_to_tell(const Params& p, const Route& route, PfMemory& m, std::int64_t tick, Vec2 nest, int& k,
                    Vec2& rel_cm) {
  if (!m.knows_way || tick % 2 == 0) return false;
  work_out_way(p, route, m);
  if (m.tell_count <= 0) return false;
  k = static_cast<int>((tick / 2) % m.tell_count);
  rel_cm = kCmPerM * (m.tell_corners[static_cast<std::size_t>(k)] - nest);
  return true;
}

bool tell_way(int id, Vec2 nest, const Params& p, const Route& route, PfMemory& m, std::int64_t tick,
              Command& cmd) {
  int k = 0;
  Vec2 rel;
  if (!p.share_way || !corner_to_tell(p, route, m, tick, nest, k, rel)) return false;
  cmd.rab_send = true;
  cmd.rab = RabPayload{};
  cmd.rab[0] = static_cast<std::uint8_t>(id & 0xff);
  cmd.rab[1] = kWayMark;
  cmd.rab[2] = static_cast<std::uint8_t>(k);
  cmd.rab[3] = static_cast<std::uint8_t>(m.tell_count);
  cmd.rab[8] = put_position_cm(cmd.rab, 4, rel.x, rel.y);
  return true;
}

bool listens_for_way(const Params& p, const PfMemory& m) {
  return p.share_way && p.share_sighting > 0.0 && m.role == PfRole::kSwarm && m.told.teller != kNobody &&
         !m.told.complete() && (m.state == PfState::kResting || m.state == PfState::kExploring);
}

bool hear_way(std::span<const RabMessage> inbox, Vec2 nest, PfMemory& m) {
  bool any = false;
  for (const RabMessage& r : inbox) {
    if (r.data[1] != kWayMark || r.sender != m.told.teller) continue;
    const int count = r.data[3];
    const int k = r.data[2];
    if (count < 1 || count > ToldWay::kMax || k >= count) continue;
    if (count != m.told.count) {  // a way other than the one begun (the teller's sighting moved on)
      m.told.count = count;
      m.told.heard = 0;
    }
    Vec2 rel;
    get_position_cm(r.data, 4, r.data[8], rel.x, rel.y);
    m.told.corners[static_cast<std::size_t>(k)] = nest + kCm * rel;
    m.told.heard |= std::uint32_t{1} << k;
    any = true;
  }
  return any;
}

}  // namespace swarmpath::sim
