// SPDX-License-Identifier: MIT
// Numbers in a range-and-bearing payload (SPEC §2.6's 10 bytes) for the messages beyond the
// protocol's own [R]: the sightings and ways robots tell (share_sighting, share_way, lead_way).
// Signed 16- and 32-bit integers, little-endian; a 16-bit value is rounded and clamped to +-32 767.
// A position in 16 bits comes with its unit, 10^e cm (e 0-3): to the centimetre within 327 m of the
// nest, to the decimetre or coarser beyond, as far as any arena reaches (kMaxArenaSide).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>

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

/// The unit of a 16-bit position: 10^e cm.
inline double unit_cm(std::uint8_t e) {
  constexpr double kUnits[4] = {1.0, 10.0, 100.0, 1000.0};
  return kUnits[e & 3U];
}

/// The exponent of the finest unit (unit_cm) in which every one of `values_cm` fits +-32 767.
inline std::uint8_t unit_exponent(std::initializer_list<double> values_cm) {
  double largest = 0.0;
  for (const double v : values_cm) largest = std::max(largest, std::abs(v));
  std::uint8_t e = 0;
  while (e < 3 && std::round(largest / unit_cm(e)) > 32767.0) ++e;
  return e;
}

/// A position relative to the nest [cm] in the two 16-bit numbers at `at` and `at + 2`, in the finest
/// unit that holds both; returns the unit's exponent, which the caller stores where its message keeps it.
inline std::uint8_t put_position_cm(RabPayload& b, std::size_t at, double x_cm, double y_cm) {
  const std::uint8_t e = unit_exponent({x_cm, y_cm});
  put_i16(b, at, x_cm / unit_cm(e));
  put_i16(b, at + 2, y_cm / unit_cm(e));
  return e;
}

/// put_position_cm's inverse, given the unit's exponent `e`: x and y [cm].
inline void get_position_cm(const RabPayload& b, std::size_t at, std::uint8_t e, double& x_cm, double& y_cm) {
  x_cm = unit_cm(e) * get_i16(b, at);
  y_cm = unit_cm(e) * get_i16(b, at + 2);
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
