// SPDX-License-Identifier: MIT
// Numbers in a range-and-bearing payload (SPEC §2.6's 10 bytes) for the messages beyond the
// protocol's own [R]: the sightings and ways robots tell (share_sighting, share_way, lead_way).
// Signed 16- and 32-bit integers, little-endian; a 16-bit value is rounded and clamped to +-32 767.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "sim/percept.hpp"

namespace swarmpath::sim {

inline void put_i16(RabPayload& b, std::size_t at, double v) {
  const auto u =
      static_cast<std::uint16_t>(static_cast<std::int16_t>(std::clamp(std::lround(v), -32767L, 32767L)));
  b[at] = static_cast<std::uint8_t>(u & 0xffU);
  b[at + 1] = static_cast<std::uint8_t>(u >> 8);
}

inline double get_i16(const RabPayload& b, std::size_t at) {
  const auto u = static_cast<std::uint16_t>(b[at] | (b[at + 1] << 8));
  return static_cast<double>(static_cast<std::int16_t>(u));
}

inline void put_i32(RabPayload& b, std::size_t at, std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  for (std::size_t k = 0; k < 4; ++k) b[at + k] = static_cast<std::uint8_t>(u >> (8 * k));
}

inline std::int32_t get_i32(const RabPayload& b, std::size_t at) {
  std::uint32_t u = 0;
  for (std::size_t k = 0; k < 4; ++k) u |= static_cast<std::uint32_t>(b[at + k]) << (8 * k);
  return static_cast<std::int32_t>(u);
}

}  // namespace swarmpath::sim
