// SPDX-License-Identifier: MIT
// Where a run's robots spent their time: robot-ticks per cell of a square grid over the arena,
// optionally only of robots showing one LED colour (e.g. GREEN, the explorers). The picture of it
// shows at a glance where explorers pile up (a field's local minimum, a corner) and which parts
// of an arena they never reach.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometry.hpp"
#include "led.hpp"
#include "percept.hpp"
#include "spatial.hpp"

namespace swarmpath::sim {

class Occupancy {
 public:
  /// Square cells of side `cell_m` covering `arena`; counts only robots with LED `only` if given.
  Occupancy(Aabb arena, double cell_m, std::optional<Led> only = std::nullopt);

  /// Books one tick: each robot (with the wanted LED) adds one to the cell it stands in; robots
  /// outside the arena are not counted.
  void add(std::span<const Pose> poses, std::span<const Led> leds);

  int cells_x() const { return frame_.nx; }

  int cells_y() const { return frame_.ny; }

  double cell_m() const { return cell_; }

  std::int64_t ticks() const { return ticks_; }

  std::optional<Led> only() const { return only_; }

  /// Robot-ticks booked in cell (ix, iy); iy = 0 is the arena's southern row.
  std::int64_t count(int ix, int iy) const { return counts_[static_cast<std::size_t>(iy * frame_.nx + ix)]; }

  /// Cell (ix, iy)'s rectangle, cut at the arena's edge (the last row and column may be narrower).
  Aabb cell_bounds(int ix, int iy) const;

  /// Mean robots per square metre of cell (ix, iy)'s part of the arena over the booked ticks (0
  /// before any).
  double density(int ix, int iy) const;

 private:
  Aabb arena_;
  double cell_;
  CellFrame frame_;
  std::optional<Led> only_;
  std::vector<std::int64_t> counts_;
  std::int64_t ticks_ = 0;
};

}  // namespace swarmpath::sim
