// SPDX-License-Identifier: MIT
// Records a run as it goes: an observer of the world after each tick (sim::run's TickObserver)
// that only reads it, so a recorded run is the same run (the same state_hash). Nothing runs and
// nothing is allocated in the tick when no recorder is attached.
#pragma once

#include <cstdint>
#include <vector>

#include "astar.hpp"
#include "metrics.hpp"
#include "params.hpp"
#include "recording.hpp"
#include "scenario.hpp"
#include "step.hpp"
#include "world.hpp"

namespace swarmpath::sim {

class Recorder {
 public:
  /// Starts recording the run of (p, s, mode, seed) with a frame every `every` ticks (>= 1): frame
  /// 0 is the world make_world builds for it, as sim::run does.
  Recorder(const Params& p, const Scenario& s, Mode mode, std::uint64_t seed, std::int64_t every);

  /// Call after every tick: a frame on every `every`-th tick, and every robot whose state code
  /// changed, with the row that fired.
  void observe(const World& w);

  /// The recording, once the run is over: the final world (a last frame when it is off the
  /// grid), the milestones, paths and result of its metrics, the A* path (`astar` when the caller
  /// has computed it, else computed here) and the names of every state code present. The recorder
  /// is spent afterwards.
  Recording finish(const World& final_world, const Metrics& m, const AStarResult* astar = nullptr);

 private:
  void add_frame(const World& w);
  void note_allocation(const World& w, std::size_t i);

  const Scenario* scenario_;
  Recording r_;
  std::vector<std::uint8_t> last_state_;
  std::vector<std::int64_t> last_done_;       ///< TA: alloc_done_tick as last seen
  std::vector<std::uint8_t> last_refounder_;  ///< TA: refounder as last seen
};

/// sim::run with a recorder attached (and `also`, when given, called after it every tick).
Recording record_run(const Params& p, const Scenario& s, Mode mode, std::uint64_t seed, std::int64_t every,
                     Metrics* metrics = nullptr, const TickObserver& also = {});

}  // namespace swarmpath::sim
