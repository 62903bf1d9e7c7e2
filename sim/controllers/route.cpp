// SPDX-License-Identifier: MIT
#include "route.hpp"

namespace swarmpath::sim {

namespace {
constexpr double kPassed = 0.25;  // [m] a crumb this near is passed (the trail's spacing)
constexpr int kLookAhead = 8;     // crumbs ahead checked for a short cut
}  // namespace

void Route::keep(const Trail& trail) {
  count_ = trail.size();
  for (int i = 0; i < count_; ++i) crumbs_[static_cast<std::size_t>(i)] = trail.crumb(i);
  next_ = 0;
  end_ = 0;
  trip_ = -1;
}

bool Route::begin(Vec2 p, Vec2 to, double seen, double along) {
  next_ = 0;
  end_ = 0;
  int last = -1;
  double best = seen;
  for (int i = 0; i < count_; ++i) {
    const double d = dist(crumbs_[static_cast<std::size_t>(i)], to);
    if (d <= best) {
      best = d;
      last = i;
    }
  }
  if (last < 0) return false;
  int first = 0;
  double nearest = 1e18;
  double walked = 0.0;  // along the way from its start to crumb i
  for (int i = 0; i <= last; ++i) {
    if (i > 0) walked += dist(crumbs_[static_cast<std::size_t>(i - 1)], crumbs_[static_cast<std::size_t>(i)]);
    if (walked > along) break;
    const double d = dist(crumbs_[static_cast<std::size_t>(i)], p);
    if (d < nearest) {
      nearest = d;
      first = i;
    }
  }
  next_ = first;
  end_ = last + 1;
  return true;
}

bool Route::next(Vec2 p, Vec2& crumb) {
  const int ahead = next_ + kLookAhead < end_ ? next_ + kLookAhead : end_ - 1;
  for (int i = ahead; i >= next_; --i) {
    if (dist(p, crumbs_[static_cast<std::size_t>(i)]) <= kPassed) {
      next_ = i + 1;
      break;
    }
  }
  if (next_ >= end_) return false;
  crumb = crumbs_[static_cast<std::size_t>(next_)];
  return true;
}

double Route::remaining(Vec2 p) const {
  if (next_ >= end_) return 0.0;
  double len = dist(p, crumbs_[static_cast<std::size_t>(next_)]);
  for (int i = next_ + 1; i < end_; ++i)
    len += dist(crumbs_[static_cast<std::size_t>(i - 1)], crumbs_[static_cast<std::size_t>(i)]);
  return len;
}

}  // namespace swarmpath::sim
