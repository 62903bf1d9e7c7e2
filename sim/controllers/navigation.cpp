// SPDX-License-Identifier: MIT
#include "navigation.hpp"

#include <cmath>

#include "sim/motion.hpp"
#include "sim/robot_model.hpp"
#include "units.hpp"

namespace swarmpath::sim {

void nav_reset(NavMemory& nav) { nav = NavMemory{}; }

bool nav_update(NavMemory& nav, const Params& p, Rng& rng, double progress_cm, const Percept& in, Vec2 wanted,
                bool crowded) {
  if (crowded) {
    nav_reset(nav);
    return false;
  }
  constexpr double kLeave = 20.0;          // cm past the start of a following that end it
  constexpr std::int64_t kEdgeLost = 100;  // ticks without a reading that end it
  const auto& dirs = proximity_directions();
  bool touching = false;
  bool way_free = true;  // nothing sensed within 60 degrees of the wanted direction
  const double wanted_len = norm(wanted);
  for (std::size_t k = 0; k < kProximityCount; ++k) {
    if (in.proximity[k] <= 0.0) continue;
    touching = true;
    if (wanted_len > 0.0 && dot(dirs[k], wanted) >= 0.5 * wanted_len) way_free = false;
  }
  if (progress_cm > nav.best + p.trap_progress) {
    nav.best = progress_cm;
    nav.stalled = 0;
  } else {
    ++nav.stalled;
  }
  if (nav.following > 0) {
    nav.off_edge = touching ? 0 : nav.off_edge + 1;
    if ((progress_cm > nav.follow_from + kLeave && way_free) || nav.off_edge >= kEdgeLost) {
      nav.following = 0;  // past the obstacle, or it is gone
      nav.side = 0;       // the next obstacle gets a fresh choice
      nav.reversed = false;
    } else if (--nav.following == 0 ||
               (!nav.reversed && static_cast<double>(nav.stalled) >= p.dead_end_traps * p.t_trap)) {
      // out of time, or a dead end (no progress for dead_end_traps T_trap, 5): turn back along the same edge
      // once; when that fails too, give up
      nav.side = static_cast<std::int8_t>(-nav.side);
      if (!nav.reversed) {
        nav.reversed = true;
        nav.following = static_cast<std::int64_t>(p.t_follow);
        nav.stalled = 0;
        nav.best = progress_cm;
      } else {
        nav.following = 0;
        nav.reversed = false;
      }
    }
  } else if (p.t_trap > 0 && static_cast<double>(nav.stalled) >= p.t_trap && touching) {
    nav.off_edge = 0;
    if (nav.side == 0) {
      // keep going the way the robot faces: the obstacle on the side that needs the smaller turn
      // (the sensed obstacle to the left of the heading -> keep it on the left), ties at random
      const Vec2 s = proximity_vector(in.proximity);
      nav.side = s.y > 1e-9 ? -1 : s.y < -1e-9 ? 1 : (rng.bernoulli(0.5) ? 1 : -1);
    }
    nav.following = static_cast<std::int64_t>(p.t_follow);
    nav.follow_from = progress_cm;
    nav.best = progress_cm;
    nav.stalled = 0;
  }
  return nav.following > 0;
}

Vec2 follow_edge(const Percept& in, int side) {
  constexpr double kSetPoint = 0.3;  // proximity magnitude of about 4 cm on two sensors
  const Vec2 s = proximity_vector(in.proximity);
  const double mag = norm(s);
  if (mag == 0.0) return unit(-side * deg2rad(45.0));
  const Vec2 away = (-1.0 / mag) * s;
  const Vec2 tangent = side > 0 ? Vec2{away.y, -away.x} : Vec2{-away.y, away.x};  // away turned -/+90 deg
  const Vec2 v = tangent + (mag - kSetPoint) * away;
  return (1.0 / norm(v)) * v;
}

namespace {

// no progress for `trap` ticks and no edge following under way: the field has trapped the robot
// (checked one tick ahead of nav_update, which would start edge following at T_trap)
bool trapped(const NavMemory& nav, const Params& p, double trap) {
  const std::int64_t stalled = trap < p.t_trap ? nav.short_stalled : nav.stalled;
  return nav.following == 0 && p.t_trap > 0 && static_cast<double>(stalled) + 1.0 >= trap;
}

// a window shorter than T_trap keeps its own record: progress of trap_progress * trap / T_trap
// restarts it, so that it asks for the rate T_trap asks for (30 cm in 100 ticks: 7.5 cm in 25),
// not trap_progress in a quarter of the time (60 % of v_max = 20 cm/s, turning round included)
void book_short(NavMemory& nav, const Params& p, double trap, double progress_cm) {
  if (!(trap < p.t_trap)) return;
  if (progress_cm > nav.short_best + p.trap_progress * trap / p.t_trap) {
    nav.short_best = progress_cm;
    nav.short_stalled = 0;
  } else {
    ++nav.short_stalled;
  }
}

// a new leg (the trail, a crumb fallen back to or skipped): no progress booked yet
void restart_progress(NavMemory& nav) {
  nav.stalled = 0;
  nav.best = -1e18;
  nav.short_stalled = 0;
  nav.short_best = -1e18;
}

}  // namespace

Vec2 nav_home(const Percept& in, const Params& p, NavMemory& nav, Rng& rng, Trail& trail, Vec2 nest,
              double trap_ticks, const Vec2* field_point, double trail_within, bool retrace) {
  const double trap = trap_ticks > 0.0 ? trap_ticks : p.t_trap;
  // trapped by the field with a trail to retrace: switch to the trail for the rest of the way
  if (!nav.on_trail) trail.touch(in.pose.p);
  if (p.way_home_leg && !nav.on_trail) trail.record_home(in.pose.p);  // R: path integration goes on
  if (p.trail_home && !nav.on_trail && !trail.empty() && trapped(nav, p, trap)) {
    nav.on_trail = true;
    trail.start_home_within(in.pose.p, nest, trail_within);
    restart_progress(nav);
    // R founder_retrace: a trail home that is the nest alone adds nothing to the field that trapped
    // the robot (the nest behind a wall): back to where it last was on its way, home from there
    if (retrace && trail.size() <= 1) nav.fell_back = trail.fall_back();
  }
  if (!nav.on_trail) {
    const Vec2 point = field_point != nullptr ? *field_point : nest;
    book_short(nav, p, trap, -kCmPerM * dist(in.pose.p, point));
    return nav_toward(in, p, nav, rng, point);
  }
  // stuck on the way to the crumb nearest it (behind a wall?), away from the nest's crowd: back to
  // a crumb it has been at, and home along the trail from there (once per leg)
  if (!nav.fell_back && trapped(nav, p, trap) && kCmPerM * dist(in.pose.p, nest) > p.nest_crowd) {
    nav.fell_back = true;
    if (trail.fall_back()) restart_progress(nav);
  }
  // a crumb it cannot get to (a robot stands on it: chain robots stop where explorers walked) is
  // passed over after T_trap ticks without progress
  if (p.skip_blocked_crumbs && !trail.empty() && trapped(nav, p, trap)) {
    trail.skip();
    restart_progress(nav);
  }
  Vec2 crumb = nest;
  const bool more = trail.next_home(in.pose.p, crumb);
  // progress along the trail: minus what is left of it (then of the last leg to the nest)
  const double left = more ? trail.remaining(in.pose.p) : dist(in.pose.p, nest);
  book_short(nav, p, trap, -kCmPerM * left);
  const Vec2 field = field_toward(in.pose, crumb);
  if (nav_update(nav, p, rng, -kCmPerM * left, in, field)) return follow_edge(in, nav.side);
  return field;
}

Vec2 nav_toward(const Percept& in, const Params& p, NavMemory& nav, Rng& rng, Vec2 point, bool crowded) {
  const Vec2 field = field_toward(in.pose, point);
  if (nav_update(nav, p, rng, -kCmPerM * dist(in.pose.p, point), in, field, crowded)) {
    return follow_edge(in, nav.side);
  }
  return field;
}

Vec2 nav_route(const Percept& in, const Params& p, NavMemory& nav, Rng& rng, Route& route, Vec2 to,
               bool crowded) {
  if (route.walking() && trapped(nav, p, p.t_trap)) {
    route.skip();
    restart_progress(nav);
  }
  const bool was_walking = route.walking();
  Vec2 crumb;
  if (!route.next(in.pose.p, crumb)) {
    if (was_walking) restart_progress(nav);  // the last leg: to the point itself
    return nav_toward(in, p, nav, rng, to, crowded);
  }
  const Vec2 field = field_toward(in.pose, crumb);
  if (nav_update(nav, p, rng, -kCmPerM * route.remaining(in.pose.p), in, field, crowded))
    return follow_edge(in, nav.side);
  return field;
}

Vec2 with_avoidance(const Percept& in, const Params& p, const NavMemory& nav, Vec2 f) {
  return (nav.following > 0 ? Vec2{} : diffusion(in.proximity, p).direction) + f;
}

}  // namespace swarmpath::sim
