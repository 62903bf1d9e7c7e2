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
  static constexpr int kHomeCapacity = 64;      ///< crumbs of the leg home by the field [R way_home_leg]
  static constexpr double kEverywhere = 1e300;  ///< [m] a `within` that every crumb is

  /// Starts a new trail at `start`.
  void reset(Vec2 start);

  /// Drops a crumb when the robot is 25 cm from the last one; back within 25 cm of an
  /// earlier crumb, it cuts the trail back to it (loop erasure: closer than a wall's thickness
  /// plus a robot's width, so the cut never joins two sides of a wall); a full trail drops half its
  /// crumbs, those nearest the line between their neighbours: the straight stretches thin out and
  /// the corners where the robot went round an obstacle stay.
  void record(Vec2 p);

  /// On the way home before taking the trail: a crumb the robot passes within 25 cm of is one it
  /// has reached; the trail home may start there.
  void touch(Vec2 p);

  /// [R way_home_leg] On the way home by the field, before taking the trail: a crumb every 25 cm
  /// of the leg home, which goes on from the trail's last crumb (path integration does not stop at
  /// the turn home); a full leg drops half its crumbs as the trail does. Taking the trail
  /// (start_home, start_home_within) or a new trip (reset) clears it.
  void record_home(Vec2 p);

  int home_size() const { return home_count_; }

  /// Crumb `i` of the leg home (0: the first after the trail's last crumb).
  Vec2 home_crumb(int i) const { return home_[static_cast<std::size_t>(i)]; }

  /// Begins the way home from `p` at the crumb nearest it (the robot may be anywhere along the
  /// trail, or beside it).
  void start_home(Vec2 p);

  /// As start_home, among the crumbs within `within` of `nest` only (all when none is).
  void start_home_within(Vec2 p, Vec2 nest, double within);

  /// The crumb nearest the robot may lie behind a wall from it: goes back to the crumb nearest home
  /// that the robot has been at (the trail's end, or one it touched since the trail's last crumb)
  /// and home from there. False when that is no farther from home than where it is going now, or
  /// once the robot has passed a crumb of the way home (the way was passable).
  bool fall_back();

  /// The next crumb homeward from `p`; crumbs within 15 cm are consumed. False when none is left.
  bool next_home(Vec2 p, Vec2& crumb);

  /// Drops the next crumb homeward (one the robot cannot reach).
  void skip() {
    if (count_ > 0) --count_;
  }

  /// The crumb whose distance from `from` is nearest `r` (within `tol`) among those nearer `nest` than
  /// `within`; false when none is.
  bool crumb_at(Vec2 from, double r, double tol, Vec2 nest, double within, Vec2& out) const;

  /// The point where the way from the nest first comes within `r` of `from` (on the leg between two
  /// crumbs); false when it never does, or starts that near.
  bool first_within(Vec2 from, double r, Vec2& out) const;

  bool empty() const { return count_ == 0; }

  /// The robot followed an obstacle's edge on this trip (cleared by reset).
  void mark_edge() { went_round_ = true; }

  bool went_round() const { return went_round_; }

  /// Length of the way home from `p` along the remaining crumbs [m].
  double remaining(Vec2 p) const;

  int size() const { return count_; }

  /// Crumb `i` (0: where the trip began) of the crumbs left.
  Vec2 crumb(int i) const { return crumbs_[static_cast<std::size_t>(i)]; }

 private:
  // the index of the crumb nearest `p` among those within `within` of `nest` (-1: none)
  int nearest_crumb(Vec2 p, Vec2 nest, double within) const;

  std::array<Vec2, kCapacity> crumbs_{};
  int count_ = 0;
  std::array<Vec2, kHomeCapacity> home_{};
  int home_count_ = 0;
  int reached_ = 0;    // the crumb nearest home that the robot has been at since the last record
  int home_from_ = 0;  // count_ when start_home chose the first crumb
  bool went_round_ = false;
};

}  // namespace swarmpath::sim
