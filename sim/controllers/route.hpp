// SPDX-License-Identifier: MIT
// The way to a sighting [R route_to_sighting]: the breadcrumbs of the trip on which a robot saw the
// goal or the chain, kept when it turned home, so that its next trip (site fidelity) retraces a way
// it knows is passable instead of heading straight at the sighting, into whatever wall lies between.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "trail.hpp"

namespace swarmpath::sim {

class Route {
 public:
  static constexpr int kCapacity = Trail::kCapacity + Trail::kHomeCapacity;

  /// Keeps the trail's crumbs, from the nest outward (the trail's remaining crumbs: a way home that
  /// has been walked in part leaves the crumbs nearer the nest); with `home_leg` [R way_home_leg],
  /// the crumbs of the leg home by the field after them, a crumb back within 25 cm of a kept one
  /// cutting the way back to it (loop erasure, as Trail::record).
  void keep(const Trail& trail, bool home_leg = false);

  /// Replaces the kept crumbs with `points` (a way told by another robot [R share_way], from the nest
  /// outward; at most kCapacity are kept).
  void assign(std::span<const Vec2> points);

  /// The way from its start to the kept crumb nearest `to` within `seen` of it, as at most
  /// `out.size()` corners into `out` (the crumbs that stay when the straight stretches between them
  /// are dropped, within 10 cm; wider when that leaves too many): the first and the last crumb always
  /// stay. Returns how many; 0 when no crumb lies within `seen` of `to`.
  int corners(Vec2 to, double seen, std::span<Vec2> out) const;

  /// Begins a way from `p` to `to`: it ends at the kept crumb nearest `to` when that lies within
  /// `seen` of it (the robot saw it from there), and starts at the crumb nearest `p` before that end
  /// among those at most `along` from the way's start along it (a robot `along` from the nest in a
  /// straight line cannot have come farther along the way: the crumbs past a wall's end are not
  /// where it stands, however near across the wall). False when no crumb lies within `seen` of `to`.
  bool begin(Vec2 p, Vec2 to, double seen, double along = Trail::kEverywhere);

  /// The next crumb of the way from `p`: crumbs within 25 cm are passed, and so are those before a
  /// later crumb within 25 cm of `p` (a short cut). False when the way has been walked.
  bool next(Vec2 p, Vec2& crumb);

  /// Passes over the next crumb (one the robot cannot reach).
  void skip() {
    if (next_ < end_) ++next_;
  }

  /// Length of the way left from `p` [m].
  double remaining(Vec2 p) const;

  /// Whether a trip to `to` that began at tick `trip` walks this way (begin was called for it).
  bool begun_for(std::int64_t trip, Vec2 to) const { return trip_ == trip && to_.x == to.x && to_.y == to.y; }

  void set_trip(std::int64_t trip, Vec2 to) {
    trip_ = trip;
    to_ = to;
  }

  bool walking() const { return next_ < end_; }

  int size() const { return count_; }

 private:
  // the kept crumb nearest `to` within `seen` of it (-1: none)
  int nearest_within(Vec2 to, double seen) const;

  std::array<Vec2, kCapacity> crumbs_{};
  int count_ = 0;
  int next_ = 0;  // the next crumb to walk to
  int end_ = 0;   // one past the last crumb of the way
  std::int64_t trip_ = -1;
  Vec2 to_{};
};

}  // namespace swarmpath::sim
