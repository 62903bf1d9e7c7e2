// SPDX-License-Identifier: MIT
#include "route.hpp"

#include <algorithm>
#include <cmath>

namespace swarmpath::sim {

namespace {
constexpr double kPassed = 0.25;    // [m] a crumb this near is passed (the trail's spacing)
constexpr double kLoop = 0.25;      // [m] back this near a kept crumb: a loop (as the trail's erasure)
constexpr int kLookAhead = 8;       // crumbs ahead checked for a short cut
constexpr double kCornerTol = 0.1;  // [m] a crumb this near the line between kept neighbours is dropped

// distance from `p` to the segment a-b [m]
double to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return dist(p, a + t * ab);
}

// Douglas-Peucker over crumbs [0, n): marks in `keep` the crumbs farther than `tol` from the line
// between the kept ones around them (an explicit stack of spans, no recursion, no allocation)
int simplify(const std::array<Vec2, Route::kCapacity>& c, int n, double tol,
             std::array<bool, Route::kCapacity>& keep) {
  std::fill(keep.begin(), keep.end(), false);
  keep[0] = true;
  keep[static_cast<std::size_t>(n - 1)] = true;
  std::array<std::array<int, 2>, Route::kCapacity> stack{};
  int top = 0;
  stack[0] = {0, n - 1};
  ++top;
  while (top > 0) {
    const auto [a, b] = stack[static_cast<std::size_t>(--top)];
    double worst = tol;
    int at = -1;
    for (int i = a + 1; i < b; ++i) {
      const double d = to_segment(c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(a)],
                                  c[static_cast<std::size_t>(b)]);
      if (d > worst) {
        worst = d;
        at = i;
      }
    }
    if (at < 0) continue;
    keep[static_cast<std::size_t>(at)] = true;
    stack[static_cast<std::size_t>(top++)] = {a, at};
    stack[static_cast<std::size_t>(top++)] = {at, b};
  }
  return static_cast<int>(std::count(keep.begin(), keep.begin() + n, true));
}

}  // namespace

void Route::assign(std::span<const Vec2> points) {
  count_ = static_cast<int>(std::min<std::size_t>(points.size(), kCapacity));
  for (int i = 0; i < count_; ++i) crumbs_[static_cast<std::size_t>(i)] = points[static_cast<std::size_t>(i)];
  next_ = 0;
  end_ = 0;
  trip_ = -1;
}

int Route::nearest_within(Vec2 to, double seen) const {
  int last = -1;
  double best = seen;
  for (int i = 0; i < count_; ++i) {
    const double d = dist(crumbs_[static_cast<std::size_t>(i)], to);
    if (d <= best) {
      best = d;
      last = i;
    }
  }
  return last;
}

int Route::corners(Vec2 to, double seen, std::span<Vec2> out) const {
  const int last = nearest_within(to, seen);
  if (last < 0 || out.empty()) return 0;
  const int n = last + 1;
  if (n == 1 || out.size() == 1) {
    out[0] = crumbs_[static_cast<std::size_t>(last)];
    return 1;
  }
  std::array<bool, kCapacity> keep{};
  double tol = kCornerTol;
  while (simplify(crumbs_, n, tol, keep) > static_cast<int>(out.size())) tol *= 2.0;
  int k = 0;
  for (int i = 0; i < n; ++i)
    if (keep[static_cast<std::size_t>(i)])
      out[static_cast<std::size_t>(k++)] = crumbs_[static_cast<std::size_t>(i)];
  return k;
}

void Route::keep(const Trail& trail, bool home_leg) {
  count_ = trail.size();
  for (int i = 0; i < count_; ++i) crumbs_[static_cast<std::size_t>(i)] = trail.crumb(i);
  for (int h = 0; home_leg && h < trail.home_size(); ++h) {
    const Vec2 c = trail.home_crumb(h);
    int back = -1;  // loop erasure: back near a kept crumb, the way since then was a detour
    for (int i = 0; i + 2 < count_ && back < 0; ++i)
      if (dist(c, crumbs_[static_cast<std::size_t>(i)]) < kLoop) back = i;
    if (back >= 0) {
      count_ = back + 1;
    } else {
      crumbs_[static_cast<std::size_t>(count_++)] = c;
    }
  }
  next_ = 0;
  end_ = 0;
  trip_ = -1;
}

bool Route::begin(Vec2 p, Vec2 to, double seen, double along) {
  next_ = 0;
  end_ = 0;
  const int last = nearest_within(to, seen);
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
