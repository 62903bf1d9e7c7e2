// SPDX-License-Identifier: MIT
#include "trail.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace swarmpath::sim {

namespace {
constexpr double kSpacing = 0.25;  // [m] between crumbs
constexpr double kNear = 0.25;     // [m] under a 30 cm wall plus two robot radii (47 cm)

// dist(p, c) < kNear, deciding most crumbs by the squared distance alone: a square above kNear^2
// by the margin (far above the rounding of either side) has a root above kNear, so only the
// crumbs close to the circle take the square root, and every answer is the same.
bool near_crumb(Vec2 p, Vec2 c) {
  constexpr double kFarSquared = kNear * kNear * (1.0 + 1e-9);
  const double d2 = norm2(p - c);
  return d2 < kFarSquared && std::sqrt(d2) < kNear;
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return dist(p, a + t * ab);
}

// Halves the crumbs [0, count), dropping one at a time the crumb that lies nearest the straight line
// between its neighbours (ties: the earlier one): the corners where the way turned round an obstacle
// stay, so that no leg of the thinned way cuts through it; the straight stretches thin out. The first
// and last crumbs stay.
void thin(std::span<Vec2> c, int& count) {
  const int target = static_cast<int>(c.size()) / 2;
  while (count > target) {
    int drop = 1;
    double least = 1e18;
    for (int i = 1; i + 1 < count; ++i) {
      const double d = distance_to_segment(c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(i - 1)],
                                           c[static_cast<std::size_t>(i + 1)]);
      if (d < least) {
        least = d;
        drop = i;
      }
    }
    for (int i = drop; i + 1 < count; ++i)
      c[static_cast<std::size_t>(i)] = c[static_cast<std::size_t>(i + 1)];
    --count;
  }
}
}  // namespace

void Trail::reset(Vec2 start) {
  count_ = 1;
  home_count_ = 0;
  reached_ = 0;
  went_round_ = false;
  crumbs_[0] = start;
}

void Trail::record(Vec2 p) {
  if (count_ > 0 && dist(p, crumbs_[static_cast<std::size_t>(count_ - 1)]) < kSpacing) return;
  // loop erasure: back near an earlier crumb, the way since then was a detour
  for (int i = 0; i + 2 < count_; ++i) {
    if (near_crumb(p, crumbs_[static_cast<std::size_t>(i)])) {
      count_ = i + 1;
      reached_ = i;
      return;
    }
  }
  if (count_ == kCapacity) thin(crumbs_, count_);
  reached_ = count_;
  crumbs_[static_cast<std::size_t>(count_++)] = p;
}

void Trail::touch(Vec2 p) {
  for (int i = 0; i < reached_; ++i) {
    if (near_crumb(p, crumbs_[static_cast<std::size_t>(i)])) {
      reached_ = i;
      return;
    }
  }
}

double Trail::remaining(Vec2 p) const {
  if (count_ == 0) return 0.0;
  double len = dist(p, crumbs_[static_cast<std::size_t>(count_ - 1)]);
  for (int i = 1; i < count_; ++i)
    len += dist(crumbs_[static_cast<std::size_t>(i - 1)], crumbs_[static_cast<std::size_t>(i)]);
  return len;
}

int Trail::nearest_crumb(Vec2 p, Vec2 nest, double within) const {
  int best = -1;
  double best_d = 1e18;
  for (int i = 0; i < count_; ++i) {
    const Vec2 c = crumbs_[static_cast<std::size_t>(i)];
    if (dist(c, nest) >= within) continue;
    const double d = dist(p, c);
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  return best;
}

void Trail::record_home(Vec2 p) {
  if (count_ == 0) return;
  const Vec2 last = home_count_ > 0 ? home_[static_cast<std::size_t>(home_count_ - 1)]
                                    : crumbs_[static_cast<std::size_t>(count_ - 1)];
  if (dist(p, last) < kSpacing) return;
  if (home_count_ == kHomeCapacity) thin(home_, home_count_);
  home_[static_cast<std::size_t>(home_count_++)] = p;
}

void Trail::start_home(Vec2 p) {
  home_count_ = 0;
  count_ = nearest_crumb(p, p, kEverywhere) + 1;  // the crumbs after it stay in the array for fall_back
  home_from_ = count_;
}

void Trail::start_home_within(Vec2 p, Vec2 nest, double within) {
  home_count_ = 0;
  const int best = nearest_crumb(p, nest, within);
  if (best < 0) {
    start_home(p);
    return;
  }
  count_ = best + 1;
  home_from_ = count_;
}

bool Trail::crumb_at(Vec2 from, double r, double tol, Vec2 nest, double within, Vec2& out) const {
  double best = tol;
  bool found = false;
  for (int i = 0; i < count_; ++i) {
    const Vec2 c = crumbs_[static_cast<std::size_t>(i)];
    if (dist(c, nest) >= within) continue;
    const double dev = std::abs(dist(c, from) - r);
    if (dev <= best) {
      best = dev;
      out = c;
      found = true;
    }
  }
  return found;
}

bool Trail::first_within(Vec2 from, double r, Vec2& out) const {
  if (count_ == 0 || dist(crumbs_[0], from) <= r) return false;
  for (int i = 1; i < count_; ++i) {
    const Vec2 a = crumbs_[static_cast<std::size_t>(i - 1)];
    const Vec2 b = crumbs_[static_cast<std::size_t>(i)];
    if (dist(b, from) > r) continue;
    // a is farther than r, b within: the circle of radius r round `from` crosses the leg a-b at
    // a + t (b - a), the smaller root of |a - from + t (b - a)|^2 = r^2 in [0, 1]
    const Vec2 ab = b - a;
    const Vec2 fa = a - from;
    const double qa = dot(ab, ab);
    const double qb = 2.0 * dot(fa, ab);
    const double qc = dot(fa, fa) - r * r;
    const double disc = std::max(0.0, qb * qb - 4.0 * qa * qc);
    const double t = qa > 0.0 ? std::clamp((-qb - std::sqrt(disc)) / (2.0 * qa), 0.0, 1.0) : 1.0;
    out = a + t * ab;
    return true;
  }
  return false;
}

bool Trail::fall_back() {
  // once past a crumb of the way home, the trail is not what trapped it
  if (count_ == 0 || count_ < home_from_ || reached_ + 1 <= count_) return false;
  count_ = reached_ + 1;
  return true;
}

bool Trail::next_home(Vec2 p, Vec2& crumb) {
  constexpr double kReached = 0.15;  // a crumb this close is consumed
  while (count_ > 0 && dist(p, crumbs_[static_cast<std::size_t>(count_ - 1)]) <= kReached) --count_;
  if (count_ == 0) return false;
  crumb = crumbs_[static_cast<std::size_t>(count_ - 1)];
  return true;
}

}  // namespace swarmpath::sim
