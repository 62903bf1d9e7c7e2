// SPDX-License-Identifier: MIT
// The controllers' units: the simulator works in metres, the camera, the medium and the params in cm
// (SPEC §1.3, §7).
#pragma once

namespace swarmpath::sim {

inline constexpr double kCm = 0.01;       ///< metres per cm
inline constexpr double kCmPerM = 100.0;  ///< cm per metre

}  // namespace swarmpath::sim
