// SPDX-License-Identifier: MIT
#include "metrics.hpp"

namespace swarmpath::sim {

void MetricsAccumulator::begin(int robots) {
  robots_ = robots;
  distance_m_ = 0;
}

Metrics MetricsAccumulator::finish(std::int64_t ticks, double dt, std::uint64_t hash) const {
  Metrics m;
  m.robots = robots_;
  m.ticks = ticks;
  m.state_hash = hash;
  m.distance_m = distance_m_;
  const double robot_seconds = static_cast<double>(robots_) * static_cast<double>(ticks) * dt;
  m.mean_speed_cm_s = robot_seconds > 0 ? 100.0 * distance_m_ / robot_seconds : 0.0;
  return m;
}

}  // namespace swarmpath::sim
