// SPDX-License-Identifier: MIT
#include "sensors.hpp"

#include <algorithm>
#include <optional>

namespace swarmpath::sim {

namespace {

constexpr int kMaxNear = 64;

// Far above the rounding of the exact tests below (values of order 1 m, errors of order 1e-16 m):
// a shortcut that skips an exact test only when it clears this margin changes no answer.
constexpr double kSafeMargin = 1e-9;  // [m]

// True when p is farther than `reach` from every point of the shape's bounding box, by more than
// kSafeMargin, so that signed_distance(shape, p) > reach too: most near-bin shapes are this far,
// and the box test spares their exact distance (a hypot).
bool beyond_bounds(const Shape& sh, Vec2 p, double reach) {
  const double r = reach + kSafeMargin;
  return p.x - sh.bounds.hi.x > r || sh.bounds.lo.x - p.x > r || p.y - sh.bounds.hi.y > r ||
         sh.bounds.lo.y - p.y > r;
}

// signed_distance(sh, p) > reach, the same answer without a box's hypot where p lies within one of
// its slabs (the distance is then the gap to the other, hypot(g, 0) = g), the usual case beside a
// wall; only points off a corner within reach take it.
bool farther_than(const Shape& sh, Vec2 p, double reach) {
  if (sh.kind != ShapeKind::kBox) return signed_distance(sh, p) > reach;
  const Vec2 q = unrotate(p - sh.center, sh.c, sh.s);
  const double dx = std::fabs(q.x) - sh.half.x;
  const double dy = std::fabs(q.y) - sh.half.y;
  if (dx > 0.0 && dy > 0.0) return dx > reach || dy > reach || signed_distance(sh, p) > reach;
  return std::max(std::max(dx, dy), 0.0) + std::min(std::max(dx, dy), 0.0) > reach;
}

// The shapes of `bins` near p that truly come within `reach` of it, in a small local list.
// (Plain arrays: left uninitialised, they cost nothing per call.)
struct NearShapes {
  int ids[kMaxNear];
  int count = 0;
  bool overflow = false;  // more than kMaxNear: fall back to the whole bin
  std::span<const int> bin;

  NearShapes(const SensorView& v, const ShapeBins& bins, Vec2 p, double reach) : bin(bins.near(p)) {
    for (const int s : bin) {
      const Shape& sh = v.shapes[static_cast<std::size_t>(s)];
      if (beyond_bounds(sh, p, reach) || farther_than(sh, p, reach)) continue;
      if (count == kMaxNear) {
        overflow = true;
        break;
      }
      ids[count++] = s;
    }
  }

  std::span<const int> list() const {
    return overflow ? bin : std::span<const int>(ids, static_cast<std::size_t>(count));
  }
};

bool blocked_by_statics(const SensorView& v, const NearShapes& near, Vec2 a, Vec2 b) {
  for (const int s : near.list()) {
    if (segment_hits(v.shapes[static_cast<std::size_t>(s)], a, b)) return true;
  }
  return false;
}

bool blocked_by_robots(const SensorView& v, int self, int target, Vec2 a, Vec2 b) {
  bool hit = false;
  const Vec2 mid = 0.5 * (a + b);
  v.grid->for_each_within(mid, 0.5 * dist(a, b) + kRobotRadius, [&](int k, Vec2 pk) {
    if (hit || k == self || k == target) return;
    hit = segment_hits_circle(pk, kRobotRadius, a, b);
  });
  return hit;
}

// A robot's LEDs form a ring of radius 9 cm (ARGoS ray-casts each LED): it is seen when the
// line to its centre, or to either of the ring's two tangent points, is clear.
bool ring_visible(const SensorView& v, const NearShapes& near, int self, int target, Vec2 from, Vec2 at) {
  const auto clear = [&](Vec2 to) {
    return !blocked_by_statics(v, near, from, to) &&
           !(v.occlude_by_robots && blocked_by_robots(v, self, target, from, to));
  };
  if (clear(at)) return true;
  if (!v.led_ring) return false;
  const Vec2 d = at - from;
  const double len = norm(d);
  if (len == 0.0) return false;
  const Vec2 side = (kLedRingRadius / len) * Vec2{-d.y, d.x};
  return clear(at + side) || clear(at - side);
}

}  // namespace

void sense_proximity(const SensorView& v, int id, std::array<double, kProximityCount>& out) {
  out.fill(0.0);
  const Pose& me = v.poses[static_cast<std::size_t>(id)];
  constexpr double R = kRobotRadius;
  constexpr double kRange = kProximityRange;
  const double reach = R + kRange;

  // robots whose body can cut a ray, in this robot's frame (at most ~24 fit around a body)
  constexpr int kMaxRobots = 48;
  double rx[kMaxRobots];
  double ry[kMaxRobots];
  int n = 0;
  v.grid->for_each_within(me.p, reach + R, [&](int j, Vec2 pj) {
    if (j == id || n == kMaxRobots) return;
    const Vec2 q = me.to_local(pj - me.p);
    rx[n] = q.x;
    ry[n++] = q.y;
  });
  // obstacles within reach
  const NearShapes near(v, *v.touch_bins, me.p, reach);
  if (n == 0 && near.count == 0 && !near.overflow) return;

  // Each ray starts on the body edge, o = R d, and runs kRange along d (robot frame).
  double best[kProximityCount];
  std::fill(best, best + kProximityCount, kNoHit);
  const auto& dirs = proximity_directions();
  // a circle of radius r centred at q (robot frame): with u = q.d, the ray's quadratic reduces to
  // b = R - u, c = |q|^2 - 2Ru + R^2 - r^2 (entry at t = -b - sqrt(b^2 - c))
  const auto circle = [&](Vec2 q, double r) {
    const double q2 = norm2(q);
    for (std::size_t k = 0; k < kProximityCount; ++k) {
      const double u = dot(q, dirs[k]);
      const double c2 = q2 - 2.0 * R * u + R * R - r * r;
      if (c2 <= 0.0) {  // the ray starts inside (bodies pressed together)
        best[k] = 0.0;
        continue;
      }
      const double b = R - u;
      if (b >= 0.0) continue;  // pointing away
      const double disc = b * b - c2;
      if (disc < 0.0) continue;
      const double t = -b - std::sqrt(disc);
      if (t <= kRange && t < best[k]) best[k] = t;
    }
  };
  for (int i = 0; i < n; ++i) circle({rx[i], ry[i]}, R);
  for (const int s : near.list()) {
    const Shape& sh = v.shapes[static_cast<std::size_t>(s)];
    if (sh.kind == ShapeKind::kCircle) {
      circle(me.to_local(sh.center - me.p), sh.radius);
      continue;
    }
    // box: work in the box's frame, where the slab test needs no rotation per ray
    const Vec2 pb = unrotate(me.p - sh.center, sh.c, sh.s);
    const double cr = me.c * sh.c + me.s * sh.s;  // robot heading relative to the box
    const double sr = me.s * sh.c - me.c * sh.s;
    // Outside a slab by g (|pb.x| - half.x = g > 0), a ray enters it within its length only if
    // it heads into it steeply enough: its start R d and its reach (R + kRange) d give
    // side * d.x <= -g / reach, side the sign of pb.x. A ray pointing elsewhere misses the box
    // (its slab test below would find t0 > t1), so it is skipped before the test's divisions.
    const auto slab_limit = [&](double centre, double half) {
      const double g = std::fabs(centre) - half;
      return g > 0.0 ? -g / reach + kSafeMargin : kNoHit;
    };
    const double side_x = pb.x > 0.0 ? 1.0 : -1.0;
    const double side_y = pb.y > 0.0 ? 1.0 : -1.0;
    const double limit_x = slab_limit(pb.x, sh.half.x);
    const double limit_y = slab_limit(pb.y, sh.half.y);
    for (std::size_t k = 0; k < kProximityCount; ++k) {
      const Vec2 d = rotate(dirs[k], cr, sr);
      if (side_x * d.x > limit_x || side_y * d.y > limit_y) continue;
      const Vec2 o = pb + R * d;
      double t0 = 0.0;
      double t1 = std::min(kRange, best[k]);
      bool miss = false;
      for (int a = 0; a < 2 && !miss; ++a) {
        const double oa = a == 0 ? o.x : o.y;
        const double da = a == 0 ? d.x : d.y;
        const double ha = a == 0 ? sh.half.x : sh.half.y;
        if (std::fabs(da) < 1e-15) {
          miss = std::fabs(oa) > ha;
          continue;
        }
        double ta = (-ha - oa) / da;
        double tb = (ha - oa) / da;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        miss = t0 > t1;
      }
      if (!miss) best[k] = t0;
    }
  }
  for (std::size_t k = 0; k < kProximityCount; ++k) {
    if (best[k] != kNoHit) out[k] = proximity_response(best[k]);
  }
}

void sense_camera(const SensorView& v, int id, std::vector<Blob>& out) {
  const Pose& me = v.poses[static_cast<std::size_t>(id)];
  const double range = v.camera_range;
  const NearShapes near(v, *v.camera_bins, me.p, range);

  const auto emit = [&](Vec2 at, Led color, int emitter, int tag) {
    const Vec2 d = at - me.p;
    const double len = norm(d);
    out.push_back(
        {color, emitter, len > 0.0 ? (1.0 / len) * me.to_local(d) : Vec2{1.0, 0.0}, 100.0 * len, tag});
  };
  // beacons first: nest (blue), goal (yellow)
  if (dist(me.p, v.nest) <= range && !blocked_by_statics(v, near, me.p, v.nest))
    emit(v.nest, Led::kBlue, kNestEmitter, kNobody);
  if (dist(me.p, v.goal) <= range && !blocked_by_statics(v, near, me.p, v.goal))
    emit(v.goal, Led::kYellow, kGoalEmitter, kNobody);
  // then robots with lit LEDs, in grid order
  v.grid->for_each_within(me.p, range, [&](int j, Vec2 pj) {
    if (j == id) return;
    const Led led = v.leds[static_cast<std::size_t>(j)];
    if (led == Led::kBlack) return;
    if (!ring_visible(v, near, id, j, me.p, pj)) return;
    emit(pj, led, j, v.tags[static_cast<std::size_t>(j)]);
  });
}

void sense_rab(const SensorView& v, int id, RabKinds interest, std::vector<RabMessage>& out) {
  const Pose& me = v.poses[static_cast<std::size_t>(id)];
  std::optional<NearShapes> near;           // found when the first message in range needs its line of sight
  const auto heard_in_row = [&](int row) {  // a row of cells some robot of which sent a kind it reads
    return (v.rab_row_kinds[static_cast<std::size_t>(row)] & interest) != 0;
  };
  const auto heard_in = [&](int cell) {  // a cell some robot of which sent a kind it reads
    return (v.rab_cell_kinds[static_cast<std::size_t>(cell)] & interest) != 0;
  };
  v.grid->for_each_within(me.p, kRabRange, heard_in_row, heard_in, [&](int j, Vec2 pj) {
    if (j == id || (v.rab_kinds[static_cast<std::size_t>(j)] & interest) == 0) return;
    if (!near) near.emplace(v, *v.rab_bins, me.p, kRabRange);
    if (blocked_by_statics(v, *near, me.p, pj)) return;
    const Vec2 d = pj - me.p;
    out.push_back({j, 100.0 * norm(d), me.to_local(d), v.rab_out[static_cast<std::size_t>(j)]});
  });
}

}  // namespace swarmpath::sim
