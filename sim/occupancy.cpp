// SPDX-License-Identifier: MIT
#include "occupancy.hpp"

#include <algorithm>
#include <stdexcept>

namespace swarmpath::sim {

namespace {

// checked before the cell frame divides by it
double positive_cell(double cell_m) {
  if (!(cell_m > 0.0)) throw std::invalid_argument("occupancy cell size must be > 0");
  return cell_m;
}

}  // namespace

Occupancy::Occupancy(Aabb arena, double cell_m, std::optional<Led> only)
    : arena_(arena),
      cell_(positive_cell(cell_m)),
      frame_(arena, cell_),
      only_(only),
      counts_(frame_.cells(), 0) {}

void Occupancy::add(std::span<const Pose> poses, std::span<const Led> leds) {
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (only_ && leds[i] != *only_) continue;
    if (arena_.contains(poses[i].p)) ++counts_[static_cast<std::size_t>(frame_.index(poses[i].p))];
  }
  ++ticks_;
}

Aabb Occupancy::cell_bounds(int ix, int iy) const {
  Aabb b = frame_.cell_bounds(iy * frame_.nx + ix);
  b.hi = {std::min(b.hi.x, arena_.hi.x), std::min(b.hi.y, arena_.hi.y)};
  return b;
}

double Occupancy::density(int ix, int iy) const {
  if (ticks_ == 0) return 0.0;
  const Aabb b = cell_bounds(ix, iy);
  const double area = (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y);
  return static_cast<double>(count(ix, iy)) / static_cast<double>(ticks_) / area;
}

}  // namespace swarmpath::sim
