// SPDX-License-Identifier: MIT
#include "trail.hpp"

namespace swarmpath::sim {

void Trail::reset(Vec2 start) {
  count_ = 1;
  crumbs_[0] = start;
  spacing_ = 0.25;
}

void Trail::record(Vec2 p) {
  if (count_ > 0 && dist(p, crumbs_[static_cast<std::size_t>(count_ - 1)]) < spacing_) return;
  // loop erasure: back near an earlier crumb, the way since then was a detour
  for (int i = 0; i + 2 < count_; ++i) {
    if (dist(p, crumbs_[static_cast<std::size_t>(i)]) < spacing_) {
      count_ = i + 1;
      return;
    }
  }
  if (count_ == kCapacity) {
    // keep crumbs 0, 2, 4, ...: the trail still starts where it started
    for (int i = 0; i < kCapacity / 2; ++i)
      crumbs_[static_cast<std::size_t>(i)] = crumbs_[static_cast<std::size_t>(2 * i)];
    count_ = kCapacity / 2;
    spacing_ *= 2.0;
  }
  crumbs_[static_cast<std::size_t>(count_++)] = p;
}

double Trail::remaining(Vec2 p) const {
  if (count_ == 0) return 0.0;
  return dist(p, crumbs_[static_cast<std::size_t>(count_ - 1)]) + static_cast<double>(count_ - 1) * spacing_;
}

void Trail::start_home(Vec2 p) {
  int best = -1;
  double best_d = 1e18;
  for (int i = 0; i < count_; ++i) {
    const double d = dist(p, crumbs_[static_cast<std::size_t>(i)]);
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  count_ = best + 1;
}

bool Trail::next_home(Vec2 p, Vec2& crumb) {
  constexpr double kReached = 0.15;  // a crumb this close is consumed
  while (count_ > 0 && dist(p, crumbs_[static_cast<std::size_t>(count_ - 1)]) <= kReached) --count_;
  if (count_ == 0) return false;
  crumb = crumbs_[static_cast<std::size_t>(count_ - 1)];
  return true;
}

}  // namespace swarmpath::sim
