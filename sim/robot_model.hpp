// SPDX-License-Identifier: MIT
// The foot-bot hardware model (SPEC §1.1, §1.3): ARGoS 3 defaults, in SI units.
#pragma once

#include <array>
#include <cstddef>

#include "vec2.hpp"

namespace swarmpath::sim {

inline constexpr double kRobotRadius = 0.085036758;  ///< body radius [m] (footbot_entity.cpp)
inline constexpr double kWheelBase = 0.14;           ///< inter-wheel distance [m]

inline constexpr std::size_t kProximityCount = 24;  ///< IR proximity ring
inline constexpr double kProximityRange = 0.10;     ///< ray length from the body edge [m]

inline constexpr double kLedRingRadius = 0.090;  ///< the 12-LED ring [m] (SPEC §1.1)

inline constexpr double kRabRange = 3.0;             ///< range-and-bearing range [m]
inline constexpr std::size_t kRabPayloadBytes = 10;  ///< range-and-bearing payload (SPEC §2.6) [bytes]

/// Angle of proximity sensor k in the robot frame [rad]: +7.5 deg, then every 15 deg (SPEC §1.1).
constexpr double proximity_angle(std::size_t k) { return deg2rad(7.5 + 15.0 * static_cast<double>(k)); }

/// Robot-frame unit vectors of the 24 proximity sensors, in sensor order.
const std::array<Vec2, kProximityCount>& proximity_directions();

/// Foot-bot IR response to an obstacle at distance d [m] from the sensor (SPEC §1.3):
/// 1 below 0.00989 m, else 0.0100527 / (d + 0.000163144) (about 0.1 at 10 cm), 0 beyond range.
constexpr double proximity_response(double d) {
  if (d > kProximityRange) return 0.0;
  if (d < 0.00989) return 1.0;
  return 0.0100527 / (d + 0.000163144);
}

}  // namespace swarmpath::sim
