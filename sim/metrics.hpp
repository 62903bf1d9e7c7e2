// SPDX-License-Identifier: MIT
// What a run measures (SPEC §4): the run itself, and for path formation the success, the ticks
// to form the path and the lengths of the subgoal, optimisation-1 and final paths.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "chain_stats.hpp"
#include "path_metrics.hpp"

namespace swarmpath::sim {

struct Metrics {
  int robots = 0;
  std::int64_t ticks = 0;        ///< ticks simulated
  std::uint64_t state_hash = 0;  ///< state_hash() of the final world
  double distance_m = 0;         ///< total distance driven by all robots [m]
  double mean_speed_cm_s = 0;    ///< distance / (robots * simulated time) [cm/s]

  // path formation (SPEC §4); lengths in table units (1 TU = 10 cm), NaN when not reached
  bool success = false;              ///< path complete within max_ticks (SPEC §4.4)
  std::int64_t ticks_to_form = -1;   ///< T_form (SPEC §4.1)
  std::int64_t ticks_to_chain = -1;  ///< T_chain: the subgoal chain reaches the nest
  std::int64_t ticks_to_opt1 = -1;   ///< T_opt1: optimisation 1 done
  std::int64_t ticks_to_goal = -1;   ///< first tick a robot was within 1 m (R_vis) of the goal [R]
  double path_length_tu = std::numeric_limits<double>::quiet_NaN();          ///< final path (§4.2)
  double subgoal_path_length_tu = std::numeric_limits<double>::quiet_NaN();  ///< at T_chain
  double opt1_path_length_tu = std::numeric_limits<double>::quiet_NaN();     ///< at T_opt1
  int path_robots = 0;                                                       ///< robots in the final chain

  // task allocation (SPEC §4.1, §4.3)
  int allocated = -1;  ///< robots that entered INITIATE_TASK (all founders' allocations, founders included)
  int recruited = 0;   ///< of them, resting robots that joined a chain's end (rest_recruit, TA row T10)
  double resource_reduction_pct = std::numeric_limits<double>::quiet_NaN();  ///< (N - allocated)/N x 100
  std::int64_t ticks_to_allocate = -1;  ///< T_alloc: DONE first broadcast
  // faults (Scenario::faults)
  int failures = 0;        ///< robots that fail-stopped during the run
  int chain_failures = 0;  ///< of them, robots showing a chain link's light (RED ... BROWN) then
  PathSnapshot subgoal_path, opt1_path, final_path;  ///< for pictures
  ChainStats chain;                                  ///< how the chain's links were laid (diagnostics)
};

/// Accumulates per-tick observations; finish() fills the final fields.
class MetricsAccumulator {
 public:
  void begin(int robots);

  /// Call after every physics step with each robot's displacement that tick [m].
  void add_distance(double metres) { distance_m_ += metres; }

  /// Call after every tick.
  void observe(const Scenario& s, const World& w);

  /// The path is complete (path-formation modes).
  bool complete() const { return path_.complete(); }

  Metrics finish(std::int64_t ticks, double dt, std::uint64_t hash) const;

 private:
  int robots_ = 0;
  double distance_m_ = 0;
  bool watch_path_ = false;
  PathObserver path_;
  ChainStatsObserver chain_;
  std::int64_t alloc_tick_ = -1;
  std::int64_t goal_tick_ = -1;
  std::vector<std::uint8_t> ever_allocated_;  ///< per robot: has entered INITIATE_TASK
  int ever_allocated_count_ = 0;
  int recruited_ = 0;             ///< allocated robots whose first allocation was row T10 (rest_recruit)
  std::uint8_t recruit_row_ = 0;  ///< ta_row_number("T10")
};

}  // namespace swarmpath::sim
