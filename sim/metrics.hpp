// SPDX-License-Identifier: MIT
// What a run measures (SPEC §4). The foundation measures the run itself; the path metrics
// join with the path-formation controller.
#pragma once

#include <cstdint>

namespace swarmpath::sim {

struct Metrics {
  int robots = 0;
  std::int64_t ticks = 0;        ///< ticks simulated
  std::uint64_t state_hash = 0;  ///< state_hash() of the final world
  double distance_m = 0;         ///< total distance driven by all robots [m]
  double mean_speed_cm_s = 0;    ///< distance / (robots * simulated time) [cm/s]
};

/// Accumulates per-tick observations; finish() fills the final fields.
class MetricsAccumulator {
 public:
  void begin(int robots);

  /// Call after every physics step with each robot's displacement that tick [m].
  void add_distance(double metres) { distance_m_ += metres; }

  Metrics finish(std::int64_t ticks, double dt, std::uint64_t hash) const;

 private:
  int robots_ = 0;
  double distance_m_ = 0;
};

}  // namespace swarmpath::sim
