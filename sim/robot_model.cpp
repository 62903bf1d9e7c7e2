// SPDX-License-Identifier: MIT
#include "robot_model.hpp"

namespace swarmpath::sim {

namespace {

struct RingDirections {
  std::array<Vec2, kProximityCount> dir;

  RingDirections() {
    for (std::size_t k = 0; k < kProximityCount; ++k) dir[k] = unit(proximity_angle(k));
  }
};

}  // namespace

const std::array<Vec2, kProximityCount>& proximity_directions() {
  static const RingDirections kRing;  // immutable after first use (thread-safe initialisation)
  return kRing.dir;
}

}  // namespace swarmpath::sim
