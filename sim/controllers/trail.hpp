// SPDX-License-Identifier: MIT
// Path integration [R]: an explorer drops a breadcrumb every 25 cm of its trip (positioning
// sensor), so that a robot heading home that a potential field cannot bring there (a partition,
// a serpentine) can retrace a way it knows is passable.
#pragma once

#include <array>
#include <cstdint>

#include "sim/vec2.hpp"

namespace swarmpath::sim {

class Trail {
 public:
  static constexpr int kCapacity = 128;

  /// Starts a new trail at `start`.
  void reset(Vec2 start);

  /// Drops a crumb when the robot is `spacing` from the last one; back within `spacing` of an
  /// earlier crumb, it cuts the trail back to it (loop erasure); a full trail keeps every other
  /// crumb and doubles its spacing (deterministic thinning).
  void record(Vec2 p);

  /// Begins the way home from `p`: drops every crumb after the one nearest `p` (the robot may be
  /// anywhere along the trail, or beside it).
  void start_home(Vec2 p);

  /// The next crumb homeward from `p`; crumbs within 15 cm are consumed. False when none is left.
  bool next_home(Vec2 p, Vec2& crumb);

  bool empty() const { return count_ == 0; }

  /// Length of the way home from `p` along the remaining crumbs (approximately) [m].
  double remaining(Vec2 p) const;

  int size() const { return count_; }

 private:
  std::array<Vec2, kCapacity> crumbs_{};
  int count_ = 0;
  double spacing_ = 0.25;  // [m]
};

}  // namespace swarmpath::sim
