// SPDX-License-Identifier: MIT
#include "occupancy.hpp"

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

double Occupancy::density(int ix, int iy) const {
  if (ticks_ == 0) return 0.0;
  return static_cast<double>(count(ix, iy)) / static_cast<double>(ticks_) / (cell_ * cell_);
}

}  // namespace swarmpath::sim
