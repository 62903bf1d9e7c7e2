// SPDX-License-Identifier: MIT
// rooms: the arena cut into a grid of rooms; a random spanning tree of doors joins them all, and
// each remaining wall gets a door with probability `loops` (more than one way round). The nest's
// room and the goal's room are drawn at least `room_distance` grid steps apart.
#include <algorithm>
#include <cstdlib>
#include <numeric>

#include "draw_support.hpp"
#include "family_list.hpp"

namespace swarmpath::sim::arenas {

namespace {

// clang-format off
constexpr FamilyParam kParams[] = {
    {"cols", 3, 1, 6, true, "", "rooms along x"},
    {"rows", 2, 1, 5, true, "", "rooms along y"},
    {"door_min", 0.9, 0.5, 3.0, false, "m", "narrowest door"},
    {"door_max", 1.5, 0.5, 3.0, false, "m", "widest door"},
    {"thickness", 0.2, 0.1, 0.5, false, "m", "wall thickness"},
    {"loops", 0.25, 0.0, 1.0, false, "", "probability of a door in a wall the spanning tree left shut"},
    {"room_distance", 1, 0, 8, true, "", "fewest grid steps between the nest's room and the goal's"},
};
// clang-format on

constexpr double kSmallestRoom = 3.6;  // the deployment square (3 m) plus its margins [m]

int find_root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)];
  return i;
}

bool draw(const ParamValues& p, Rng& rng, Draft& d) {
  const Aabb in = interior(d.arena_size);
  const int cols = p.integer("cols"), rows = p.integer("rows");
  const double t = p("thickness");
  const double rw = (in.hi.x - in.lo.x) / cols, rh = (in.hi.y - in.lo.y) / rows;
  const auto room_box = [&](int i, int j) {
    return Aabb{{in.lo.x + i * rw, in.lo.y + j * rh}, {in.lo.x + (i + 1) * rw, in.lo.y + (j + 1) * rh}};
  };

  // the walls between neighbouring rooms: (a, b) with b east of or north of a
  struct Edge {
    int a, b;
  };

  std::vector<Edge> edges;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < cols; ++i) {
      if (i + 1 < cols) edges.push_back({j * cols + i, j * cols + i + 1});
      if (j + 1 < rows) edges.push_back({j * cols + i, (j + 1) * cols + i});
    }
  }
  // Fisher-Yates with our own stream, then Kruskal: a random spanning tree of doors
  for (std::size_t k = edges.size(); k > 1; --k) std::swap(edges[k - 1], edges[rng.below(k)]);
  std::vector<int> parent(static_cast<std::size_t>(cols * rows));
  std::iota(parent.begin(), parent.end(), 0);
  for (const Edge& e : edges) {
    const int ra = find_root(parent, e.a), rb = find_root(parent, e.b);
    const bool tree = ra != rb;
    if (tree) parent[static_cast<std::size_t>(ra)] = rb;
    const bool door = tree || rng.bernoulli(p("loops"));
    const bool vertical = e.b == e.a + 1;  // a wall along y between east-west neighbours
    const Aabb ra_box = room_box(e.a % cols, e.a / cols);
    const double at = vertical ? ra_box.hi.x : ra_box.hi.y;  // the wall's centre line
    const double s0 = vertical ? ra_box.lo.y : ra_box.lo.x;
    const double s1 = vertical ? ra_box.hi.y : ra_box.hi.x;
    const auto wall = [&](double u0, double u1) {
      if (u1 - u0 < 0.01) return;
      if (vertical) {
        add_wall(d, {at, u0}, {at, u1}, t);
      } else {
        add_wall(d, {u0, at}, {u1, at}, t);
      }
    };
    if (!door) {
      wall(s0 - 0.5 * t, s1 + 0.5 * t);
      continue;
    }
    const double w = mm(rng.uniform(p("door_min"), p("door_max")));
    const double c = mm(rng.uniform(s0 + 0.5 * t + 0.3 + 0.5 * w, s1 - 0.5 * t - 0.3 - 0.5 * w));
    wall(s0 - 0.5 * t, c - 0.5 * w);
    wall(c + 0.5 * w, s1 + 0.5 * t);
  }
  // the nest's room, then a goal room far enough away
  const int nest_room = static_cast<int>(rng.below(static_cast<std::uint64_t>(cols * rows)));
  std::vector<int> far;
  for (int r = 0; r < cols * rows; ++r) {
    const int steps = std::abs(r % cols - nest_room % cols) + std::abs(r / cols - nest_room / cols);
    if (steps >= p.integer("room_distance")) far.push_back(r);
  }
  if (far.empty()) return false;
  const int goal_room = far[rng.below(far.size())];
  const Aabb nest_box =
      shrink(room_box(nest_room % cols, nest_room / cols), 0.5 * t + 0.5 * kDeploySide + kDeployMargin);
  const Aabb goal_box = shrink(room_box(goal_room % cols, goal_room / cols), 0.5 * t + kGoalMargin);
  if (empty(nest_box) || empty(goal_box)) return false;
  d.nest = mm(uniform_in(rng, nest_box));
  d.goal = mm(uniform_in(rng, goal_box));
  d.deployment = square_at(d.nest, kDeploySide);
  return true;
}

std::string check(const ParamValues& p, std::string& key) {
  std::string e = ordered(p, "door_min", "door_max", key);
  if (!e.empty()) return e;
  const int cols = p.integer("cols"), rows = p.integer("rows");
  if (cols * rows < 2) {
    key = "cols";
    return "one room is no maze: cols x rows must be at least 2";
  }
  const double rw = (p("width") - 2 * kBoundary) / cols, rh = (p("height") - 2 * kBoundary) / rows;
  if (rw - p("thickness") < kSmallestRoom) {
    key = "cols";
    return "rooms would be " + toml_number(mm(rw)) + " m wide; the nest's deployment square needs " +
           toml_number(kSmallestRoom) + " m plus the wall (fewer cols or a wider arena)";
  }
  if (rh - p("thickness") < kSmallestRoom) {
    key = "rows";
    return "rooms would be " + toml_number(mm(rh)) + " m deep; the nest's deployment square needs " +
           toml_number(kSmallestRoom) + " m plus the wall (fewer rows or a taller arena)";
  }
  if (p("door_max") > std::min(rw, rh) - p("thickness") - 0.6) {
    key = "door_max";
    return "a door must fit its wall with 0.3 m to spare at each end (walls are " +
           toml_number(mm(std::min(rw, rh))) + " m)";
  }
  if (p.integer("room_distance") > cols + rows - 2) {
    key = "room_distance";
    return "no two rooms of a " + std::to_string(cols) + " x " + std::to_string(rows) + " grid are " +
           std::to_string(p.integer("room_distance")) + " steps apart (at most " +
           std::to_string(cols + rows - 2) + ")";
  }
  return {};
}

}  // namespace

const Family& rooms_family() {
  static const Family f{"rooms", "a grid of rooms joined by doors (a random spanning tree plus loops)",
                        kParams, draw, check};
  return f;
}

}  // namespace swarmpath::sim::arenas
