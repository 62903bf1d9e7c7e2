// SPDX-License-Identifier: MIT
#include "sighting_share.hpp"

#include <cmath>
#include <cstdint>

#include "units.hpp"

namespace swarmpath::sim {

namespace {

// payload: byte 0 the sender's id, byte 1 this mark, bytes 2-5 and 6-9 the sighting's x and y
// relative to the nest in cm (signed 32-bit, little-endian). Path formation sends no other message.
constexpr std::uint8_t kSightingMark = 0x53;

void put_i32(RabPayload& b, std::size_t at, std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  for (std::size_t k = 0; k < 4; ++k) b[at + k] = static_cast<std::uint8_t>(u >> (8 * k));
}

std::int32_t get_i32(const RabPayload& b, std::size_t at) {
  std::uint32_t u = 0;
  for (std::size_t k = 0; k < 4; ++k) u |= static_cast<std::uint32_t>(b[at + k]) << (8 * k);
  return static_cast<std::int32_t>(u);
}

}  // namespace

bool may_tell(const Params& p, const PfMemory& m, std::int64_t tick) {
  if (p.share_after_trips > 0.0) return static_cast<double>(m.fruitless_trips) >= p.share_after_trips;
  return static_cast<double>(tick) >= p.share_after;
}

bool tells_sighting(const Params& p, const PfMemory& m, double nest_distance_cm, std::int64_t tick) {
  return p.share_sighting > 0.0 && may_tell(p, m, tick) && m.role == PfRole::kSwarm && m.has_sighting &&
         nest_distance_cm <= p.share_sighting &&
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
  return true;
}

}  // namespace swarmpath::sim
