// SPDX-License-Identifier: MIT
// What the families share when they draw: the arena's interior, the deployment square of SPEC
// §3.3, walls as boxes, coordinates rounded to whole millimetres (readable files), the nest and
// goal at a drawn distance, and a clutter of cylinders and rotated boxes that never closes a
// passage a robot could use.
#pragma once

#include <utility>
#include <vector>

#include "family.hpp"
#include "sim/geometry.hpp"

namespace swarmpath::sim::arenas {

inline constexpr double kBoundary = 0.1;      ///< boundary wall thickness (SPEC §3.3) [m]
inline constexpr double kDeploySide = 3.0;    ///< the deployment square's side (SPEC §3.3) [m]
inline constexpr double kDeployMargin = 0.2;  ///< deployment square to any wall or obstacle [m]
inline constexpr double kGoalMargin = 0.5;    ///< goal to the boundary walls and obstacles [m]

/// `v` rounded to whole millimetres.
double mm(double v);
Vec2 mm(Vec2 v);

/// A yaw drawn uniformly in [0, 180) degrees, rounded to 0.1 degree, in radians.
double draw_yaw(Rng& rng);

/// The arena's interior (inside the boundary walls), centred at the origin.
Aabb interior(Vec2 arena_size);

/// `a` shrunk by `m` on every side (may come out empty: lo > hi).
Aabb shrink(const Aabb& a, double m);

bool empty(const Aabb& a);

/// A point drawn uniformly in `a` (which must not be empty).
Vec2 uniform_in(Rng& rng, const Aabb& a);

/// True when `inner` lies inside `outer`.
bool contains(const Aabb& outer, const Aabb& inner);

/// The square of side `side` centred at `c`.
RectRegion square_at(Vec2 c, double side);

/// A wall of thickness `t` from `a` to `b` (centre line), as one box.
void add_wall(Draft& d, Vec2 a, Vec2 b, double t);

/// The draft's boxes and cylinders as shapes (boundary walls excluded).
std::vector<Shape> draft_shapes(const Draft& d);

/// The smallest distance from `p` to the draft's boxes and cylinders (+infinity when none).
double obstacle_clearance(const Draft& d, Vec2 p);

/// The region the nest may take so that the deployment square keeps kDeployMargin from the walls.
Aabb nest_region(Vec2 arena_size);

/// Draws the nest (anywhere its deployment square fits) and a goal at a distance in [dmin, dmax]
/// in a uniform direction, kGoalMargin inside the walls and outside the deployment square grown by
/// kGoalMargin. False when 64 tries found none.
bool draw_nest_goal(Rng& rng, Vec2 arena_size, double dmin, double dmax, Vec2& nest, Vec2& goal);

/// The layout of the families whose walls stand across the arena: the nest in the west (at most
/// `band` m east of the westmost place its deployment square fits), the goal 0.6-2.5 m from the
/// east wall. Returns the stretch [x_lo, x_hi] between them that walls may take, 0.8 m clear of
/// the deployment square and of the goal.
std::pair<double, double> draw_west_to_east(Rng& rng, Draft& d, double band);

/// Clutter: cylinders (radius in [r_min, r_max]) and rotated boxes (sides in [2 r_min, 2 r_max])
/// until they cover `coverage` of the interior.
struct ClutterSpec {
  double coverage = 0.0;
  double r_min = 0.2;
  double r_max = 0.6;
  double box_fraction = 0.4;  ///< the share of boxes among the obstacles
  double gap = 0.6;           ///< free gap kept around every new obstacle [m]
  int max_count = 0;          ///< stop after this many obstacles (0: only the coverage counts)
};

/// Scatters clutter into `d`: every new obstacle keeps `gap` from the boundary walls and from every
/// obstacle already there (by its bounding circle, so never less), stays `gap` out of the
/// deployment region and kGoalMargin + `gap` from the goal. A gap wider than a robot keeps the
/// free space connected. Stops at the coverage, at max_count, or after 400 failed placements in a
/// row.
void scatter_clutter(Draft& d, Rng& rng, const ClutterSpec& spec);

}  // namespace swarmpath::sim::arenas
